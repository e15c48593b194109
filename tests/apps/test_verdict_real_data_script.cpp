// docs/lab/verdict/verdict_real_data.sh records an output with a class missing as a failure
// of that class's rows and goes on with the batch (it stopped the whole batch there). Needs R with
// spatstat.data (scripts/setup.sh installs it): skipped, saying why, without it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/formats/point_io.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace ppsynth;

namespace {

// The exemplar tiled 2 x 2 (the default output's size), keeping the classes in `keep`.
PointSet tiled(const PointSet& ex, const std::vector<int>& keep) {
  const Domain E = ex.domain();
  PointSet out(Domain{0, 0, 2 * E.width(), 2 * E.height()});
  out.set_class_labels(ex.class_labels());
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (size_t k = 0; k < ex.size(); ++k)
        if (std::find(keep.begin(), keep.end(), ex.cls(k)) != keep.end())
          out.add({ex[k].x + i * E.width(), ex[k].y + j * E.height()}, ex.cls(k));
  return out;
}

}  // namespace

TEST_CASE("verdict_real_data.sh records a missing class as a failure and goes on", "[apps][verdict_honest][script]") {
  const auto d = test::scratch_dir("verdict_real_data");
  const std::string root = PPSYNTH_SOURCE_DIR;
  if (test::run_program("Rscript", "-e 'library(spatstat.data)'").status != 0) {
    WARN("skipped: Rscript with spatstat.data is not installed (scripts/setup.sh installs it)");
    return;
  }
  REQUIRE(test::run_program("Rscript", root + "/scripts/spatstat_export.R " + (d / "exemplars").string() + " amacrine").status == 0);
  const PointSet ex = read_points((d / "exemplars" / "amacrine.txt").string());
  REQUIRE(ex.num_classes() == 2);
  // The fitted draw and tiled_copy's run: whole copies; gabor's run: class 0 only.
  fs::create_directories(d / "fitted");
  write_points((d / "fitted" / "amacrine_d095.txt").string(), tiled(ex, {0, 1}));
  for (const auto& [method, keep] : std::vector<std::pair<std::string, std::vector<int>>>{{"gabor", {0}}, {"tiled_copy", {0, 1}}}) {
    const fs::path run = d / "runs" / ("amacrine_" + method + "_s95");
    fs::create_directories(run);
    write_points((run / "output.txt").string(), tiled(ex, keep));
    std::ofstream(run / "run.json") << "{}\n";
  }
  const auto r = test::run_program("cd " + root + " && VERDICT_SYNTHESIZE=no PPSYNTH_THREADS=1",
                                   "docs/lab/verdict/verdict_real_data.sh " + d.string() + " amacrine 'gabor tiled_copy' 95");
  INFO(r.output);
  REQUIRE(r.status == 0);
  std::ifstream in(d / "results.tsv");
  std::stringstream results;
  results << in.rdbuf();
  INFO(results.str());
  CHECK(results.str().find("amacrine\tgabor\t95\t") != std::string::npos);
  CHECK(results.str().find("class 1=FAIL") != std::string::npos);
  CHECK(results.str().find("amacrine\ttiled_copy\t95\t") != std::string::npos);  // the batch went on
  CHECK(r.output.find("| amacrine | gabor | 95 | all ") != std::string::npos);
  CHECK(r.output.find("class 1 0/1") != std::string::npos);
}
