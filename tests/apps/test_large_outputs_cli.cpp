// `ppsynth synthesize --size W H` / `--points N` end to end (--quick): the output's domain
// and count, bad sizes refused with nothing written, and the peak resident memory of a run
// that does not grow with the output (window by window: optim/gabor/windows/window_plan.hpp).
#include <catch2/catch.hpp>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/formats/point_io.hpp"
#include "core/formats/text_table.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kLines = std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/lines.json";

ppsynth::test::CommandResult ppsynth_cmd(const std::string& args) {
  return ppsynth::test::run_program(ppsynth::test::ppsynth_binary(), args, "PPSYNTH_THREADS=1");
}

}  // namespace

TEST_CASE("synthesize --size and --points make outputs of that size in exemplar units", "[apps][synthesize][windows]") {
  auto d = ppsynth::test::scratch_dir("cli_size");
  auto r = ppsynth_cmd("synthesize " + kLines + " --quick -q --size 5 3 --set snapshots=false -o " + (d / "a").string());
  REQUIRE(r.status == 0);
  const auto out = ppsynth::read_points((d / "a" / "output.txt").string());
  CHECK(out.domain().x1 == 5);
  CHECK(out.domain().y1 == 3);
  CHECK(std::abs(static_cast<double>(out.size()) - 20 * 15) < 0.1 * 20 * 15);  // 20 points per exemplar unit^2

  r = ppsynth_cmd("synthesize " + kLines + " --quick -q --points 500 --set output.border=published --set snapshots=false -o " +
                  (d / "b").string());
  REQUIRE(r.status == 0);
  CHECK(ppsynth::read_points((d / "b" / "output.txt").string()).size() == 500);

  for (const std::string bad : {"--size 5", "--size 5 0", "--points 0", "--size 2 2 --points 10", "--set output.size=[1e9,1]"}) {
    INFO(bad);
    r = ppsynth_cmd("synthesize " + kLines + " --quick -q " + bad + " -o " + (d / "bad").string());
    CHECK(r.status != 0);
    CHECK_FALSE(fs::exists(d / "bad" / "output.txt"));
  }
}

TEST_CASE("the peak memory of a window-by-window run does not grow with the output", "[apps][synthesize][windows]") {
  // 96-position windows (4 exemplar units at --quick's 24 per unit): a 5 x 5 output takes 4
  // windows, a 15 x 15 one (9 times the points) about 64. Rasterized whole, the larger canvas
  // would hold a 374 x 374 grid's maps and activations instead of 96 x 96 (about +180 MiB).
  auto d = ppsynth::test::scratch_dir("cli_memory");
  double peak[2];
  int i = 0;
  for (const std::string size : {"5 5", "15 15"}) {
    const auto dir = d / ("s" + std::to_string(i));
    auto r = ppsynth_cmd("synthesize " + kLines + " --quick -q --size " + size +
                         " --set method.window.pixels=96 --set snapshots=false --set evaluate=false -o " + dir.string());
    REQUIRE(r.status == 0);
    const auto run = nlohmann::json::parse(ppsynth::read_file_text(dir / "run.json"));
    peak[i++] = run["peak_rss_mib"].get<double>();
  }
  INFO("peak resident memory: " << peak[0] << " MiB (5 x 5), " << peak[1] << " MiB (15 x 15)");
  CHECK(peak[1] <= 1.1 * peak[0] + 30);
}

TEST_CASE("a window run's snapshots show each window's grid, not the whole canvas", "[apps][synthesize][windows]") {
  // One snapshot per window. Were each the whole canvas, their size would grow with the
  // area squared (windows x points): 1.1 GB of snapshots for 100,000 points of lines.
  auto d = ppsynth::test::scratch_dir("cli_window_snapshots");
  const auto dir = d / "run";
  auto r = ppsynth_cmd("synthesize " + kLines + " --quick -q --size 12 12 --set method.window.pixels=96 --set evaluate=false -o " +
                       dir.string());
  REQUIRE(r.status == 0);
  const auto out = ppsynth::read_points((dir / "output.txt").string());
  const auto run = nlohmann::json::parse(ppsynth::read_file_text(dir / "run.json"));
  const auto& w = run["method_stats"]["windows"];
  const int windows = w["nx"].get<int>() * w["ny"].get<int>();
  REQUIRE(windows >= 9);
  size_t files = 0, shown = 0;
  for (const auto& e : fs::directory_iterator(dir / "snapshots"))
    if (e.path().extension() == ".txt") {
      const size_t n = ppsynth::read_points(e.path().string()).size();
      INFO(e.path().filename().string() << ": " << n << " points of the output's " << out.size());
      CHECK(n > 0);
      CHECK(n < out.size());
      ++files;
      shown += n;
    }
  CHECK(files == static_cast<size_t>(windows));
  // A window's grid is its interior (1/windows of the canvas) and two margins.
  CHECK(shown < static_cast<size_t>(windows) * out.size() / 3);
}
