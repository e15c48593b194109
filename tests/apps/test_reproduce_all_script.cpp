// scripts/reproduce_all.sh, the paper's whole plan: its arguments are checked before anything
// is written. An option in the place of OUT_DIR (`--help`, `--seeds 95-99` first) once became a
// directory named after it and started every config's runs there.
#include <catch2/catch.hpp>

#include <filesystem>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace ppsynth;
namespace fs = std::filesystem;

TEST_CASE("reproduce_all.sh --help prints its usage and runs nothing", "[apps][script][reproduce_all]") {
  const auto d = test::scratch_dir("reproduce_all_help");
  const auto r = test::run_program(std::string(PPSYNTH_SOURCE_DIR) + "/scripts/reproduce_all.sh", "--help", "cd " + d.string() + " &&");
  INFO(r.output);
  CHECK(r.status == 0);
  CHECK(r.output.find("Usage: scripts/reproduce_all.sh [OUT_DIR]") != std::string::npos);
  CHECK(fs::is_empty(d));
}

TEST_CASE("reproduce_all.sh refuses an option where OUT_DIR goes, and an unknown config, before any run",
          "[apps][script][reproduce_all]") {
  const auto d = test::scratch_dir("reproduce_all_bad");
  const std::string script = std::string(PPSYNTH_SOURCE_DIR) + "/scripts/reproduce_all.sh";
  const std::string bin = test::ppsynth_binary();
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"--seeds 95-99", "'--seeds' where OUT_DIR and PPSYNTH_BINARY go"},
           {"out --quick", "'--quick' where OUT_DIR and PPSYNTH_BINARY go"},
           {"out " + bin + " --only 'fig04 fig99'", "--only names 'fig99'"}}) {
    const auto r = test::run_program(script, args, "cd " + d.string() + " &&");
    INFO(args << "\n" << r.output);
    CHECK(r.status == 2);
    CHECK(r.output.find(message) != std::string::npos);
    CHECK(fs::is_empty(d));  // nothing written: no OUT_DIR, no directory named after an option
  }
}
