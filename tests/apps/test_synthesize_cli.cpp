// The `ppsynth synthesize` command end to end (--quick): the run directory's contents,
// byte-identical output for the same seed, and bad input refused with nothing written.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/formats/text_table.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

int run(const std::string& args) {
  const std::string cmd = ppsynth::test::ppsynth_binary() + " " + args + " > /dev/null 2>&1";
  return WEXITSTATUS(std::system(cmd.c_str()));
}

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";

}  // namespace

TEST_CASE("synthesize --quick writes a complete run directory", "[apps][synthesize]") {
  auto d = ppsynth::test::scratch_dir("cli_run");
  REQUIRE(run("synthesize " + kLines + " --quick -q -o " + (d / "a").string()) == 0);
  for (auto f : {"output.txt", "output.gabor.txt", "init.txt", "exemplar_vs_output.png", "loss.csv", "loss.png",
                 "config.json", "run.json", "metrics.json", "pcf.png", "snapshots/stage01.png", "snapshots/stage02.txt"})
    CHECK(fs::exists(d / "a" / f));
  CHECK_FALSE(fs::exists(d / "a.partial"));
  // 20 exemplar points -> 80 output points (+ 1 header line and comment lines)
  std::ifstream out(d / "a" / "output.txt");
  int points = 0;
  for (std::string line; std::getline(out, line);)
    if (!line.empty() && line[0] != '#') ++points;
  CHECK(points == 80);
  // Same config and seed: byte-identical output.
  REQUIRE(run("synthesize " + kLines + " --quick -q -o " + (d / "b").string()) == 0);
  CHECK(ppsynth::read_file_text(d / "a" / "output.txt") == ppsynth::read_file_text(d / "b" / "output.txt"));
  REQUIRE(run("synthesize " + kLines + " --quick -q --seed 7 -o " + (d / "c").string()) == 0);
  CHECK(ppsynth::read_file_text(d / "a" / "output.txt") != ppsynth::read_file_text(d / "c" / "output.txt"));
}

TEST_CASE("synthesize refuses bad input and writes nothing", "[apps][synthesize]") {
  auto d = ppsynth::test::scratch_dir("cli_bad");
  CHECK(run("synthesize " + kLines + " --quick -o " + (d / "x").string() + " --set method.c3=1") == 2);
  CHECK(run("synthesize --exemplar " + (d / "missing.txt").string() + " --quick -o " + (d / "y").string()) == 2);
  std::ofstream(d / "bad.txt") << "0.1 0.2\n0.3 nan\n";
  CHECK(run("synthesize --exemplar " + (d / "bad.txt").string() + " --quick -o " + (d / "z").string()) == 2);
  CHECK_FALSE(fs::exists(d / "x"));
  CHECK_FALSE(fs::exists(d / "y"));
  CHECK_FALSE(fs::exists(d / "z"));
}
