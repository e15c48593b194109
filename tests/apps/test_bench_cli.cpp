// `ppsynth bench` on a tiny grid: it reports both convolution floors (float32 and bf16
// channels-last) with the iteration's ratio to each, and it times the finest sigma's grid,
// so a config with per-sigma grids is timed on the grid its expensive stage runs (the same
// as the config without them), and its phase and run-iteration figures agree on it.
// No assertion on time: only that the figures exist and are consistent.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>

#include "core/config/config.hpp"
#include "core/processor.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";
// 16 x 16 exemplar grid (32 x 32 output), 8 filters: a second per bench.
const std::string kTiny = " --reps 1 --skip-setup -q --set method.grid.res=16 --set method.feature_net.channels=8";

ppsynth::json bench(const std::string& extra, const std::string& file, const std::string& config = kLines) {
  const std::string cmd =
      ppsynth::test::ppsynth_binary() + " bench " + config + kTiny + extra + " --json " + file + " > /dev/null 2>&1";
  REQUIRE(WEXITSTATUS(std::system(cmd.c_str())) == 0);
  std::ifstream in(file);
  return ppsynth::json::parse(in);
}

}  // namespace

TEST_CASE("bench reports the float32 and bf16 floors and times the finest sigma's grid", "[apps][bench]") {
  const auto d = ppsynth::test::scratch_dir("cli_bench");
  const auto plain = bench("", (d / "plain.json").string());
  // No bf16 floor where no bf16 convolution runs (an AVX-512 CPU under the AVX2 cap).
  REQUIRE(plain["floors"].size() == (ppsynth::cpu_isa().bf16_unavailable ? 1u : 2u));
  CHECK(plain["floors"][0]["path"] == "float32");
  if (plain["floors"].size() == 2) CHECK(plain["floors"][1]["path"] == "bfloat16 channels-last");
  for (const auto& f : plain["floors"]) {
    CHECK(f["conv_gflops"].get<double>() > 0);
    CHECK(f["floor_s"].get<double>() > 0);
    CHECK(f["iteration_over_floor"].get<double>() > 0);
  }
  CHECK(plain["output_grid"] == 32);
  CHECK(plain["run_iteration_median_s"].get<double>() > 0);

  // Per-sigma grids: the coarser sigmas get coarser grids, the finest keeps the full one,
  // and that is the grid bench times.
  const auto per_sigma = bench(" --set method.grid.per_sigma=true", (d / "per_sigma.json").string());
  CHECK(per_sigma["output_grid"] == plain["output_grid"]);
  CHECK(per_sigma["net_gflop_per_iteration"] == plain["net_gflop_per_iteration"]);
}

TEST_CASE("bench refuses a method it cannot time", "[apps][bench]") {
  const auto d = ppsynth::test::scratch_dir("cli_bench_bad");
  const std::string cmd = ppsynth::test::ppsynth_binary() + " bench " + kLines + " --set method.type=tiled_copy -q > " +
                          (d / "out.txt").string() + " 2>&1";
  CHECK(WEXITSTATUS(std::system(cmd.c_str())) == 2);
}

TEST_CASE("bench times a run's first stage only: a two-class exemplar's run iterations are all positive", "[apps][bench]") {
  // Each stage's clock starts at 0: the iterations of the second class's stage, taken as the
  // first's continuation, gave a negative run iteration (-0.40 s on amacrine).
  const auto d = ppsynth::test::scratch_dir("cli_bench_classes");
  const auto two = bench("", (d / "two.json").string(), std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/poisson_n64c2_point.json");
  CHECK(two["run_iteration_min_s"].get<double>() > 0);
  CHECK(two["run_iteration_median_s"].get<double>() >= two["run_iteration_min_s"].get<double>());
}
