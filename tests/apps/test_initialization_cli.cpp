// What `ppsynth synthesize` initializes is said before it starts: a log line with the points
// and the canvas (optim/steps/initializer.hpp), and a canvas beyond the memory is refused
// first, naming the pad when the pad makes it (optim/run/run_spec.cpp, check_synthesis_size).
#include <catch2/catch.hpp>

#include <filesystem>

#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";

ppsynth::test::CommandResult ppsynth_cmd(const std::string& args, const std::string& env = "") {
  return ppsynth::test::run_program(ppsynth::test::ppsynth_binary(), args, "PPSYNTH_THREADS=1 " + env);
}

}  // namespace

TEST_CASE("synthesize logs the points and the canvas it initializes", "[apps][synthesize][init]") {
  auto d = ppsynth::test::scratch_dir("cli_init_log");
  // lines: 20 points per exemplar unit^2; a 2 x 1 output padded by 0.5 is a 3 x 2 canvas.
  auto r = ppsynth_cmd("synthesize " + kLines + " --quick --size 2 1 --set output.pad=0.5 --set evaluate=false " +
                       "--set snapshots=false -o " + (d / "rect").string());
  INFO(r.output);
  REQUIRE(r.status == 0);
  CHECK(r.output.find("initializing 120 points on the canvas [-0.5, 2.5] x [-0.5, 1.5] (3 x 2, area 6)") != std::string::npos);
  // The paper's unit square: u^2 = 4 times the exemplar's 20 points.
  r = ppsynth_cmd("synthesize " + kLines + " --quick --set evaluate=false --set snapshots=false -o " + (d / "square").string());
  REQUIRE(r.status == 0);
  CHECK(r.output.find("initializing 80 points on the canvas [0, 1] x [0, 1] (1 x 1, area 1)") != std::string::npos);
}

TEST_CASE("a padded canvas beyond the memory is refused before anything starts, naming output.pad",
          "[apps][synthesize][init]") {
  auto d = ppsynth::test::scratch_dir("cli_init_pad");
  // 1 x 1 exemplar units padded by 100 (inside the documented bound): a 201 x 201 canvas,
  // 808,000 points of lines.
  const auto r = ppsynth_cmd("synthesize " + kLines + " --quick --size 1 1 --set output.pad=100 -o " + (d / "run").string(),
                             "PPSYNTH_MEMORY_LIMIT_MB=100");
  INFO(r.output);
  CHECK(r.status == 2);
  CHECK(r.output.find("output.pad 100: a 201 x 201 canvas") != std::string::npos);
  CHECK(r.output.find("initializing") == std::string::npos);
  CHECK_FALSE(fs::exists(d / "run"));
}
