// The scorecard's periodicity line (core/metrics/periodicity.hpp): a tiled copy of the
// exemplar repeats with its period and is flagged, on whole and on cut tiles; independent
// realizations (a jittered grid of another seed, Poisson disk, uniform) are not; the
// scorecard's periodicity and border lines appear in eval's JSON, its table and gather's values.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/error.hpp"
#include "core/generators/lattices.hpp"
#include "core/generators/poisson_disk.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/evaluation_text.hpp"
#include "core/metrics/metric_values.hpp"
#include "core/metrics/periodicity.hpp"

using namespace ppsynth;

namespace {

bool periodic(const PointSet& ex, const PointSet& out, double zoom) {
  const auto j = periodicity_report(ex, out, zoom, PeriodicityOptions{});
  INFO("ratio " << j["ratio"] << ", periods " << j["periods"]);
  REQUIRE(j["periodic"].is_boolean());
  return j["periodic"].get<bool>();
}

EvalOptions scorecard_only() {
  EvalOptions o;
  o.verdict = false;
  o.second_order = false;
  o.include_curves = false;
  return o;
}

}  // namespace

TEST_CASE("periodicity: a tiled copy of the exemplar is periodic, on whole and on cut tiles", "[scorecard]") {
  // PointSet::tiled_over cuts the tiles at the output's edges, as the tiled_copy method does.
  for (const bool regular : {false, true}) {
    INFO("Poisson disk exemplar: " << regular);
    const PointSet ex = regular ? poisson_disk_points(100, 3) : uniform_points(100, 4);
    // 2 x 2 whole tiles (the unit-square output at zoom 1/2, as tiled_copy makes it).
    CHECK(periodic(ex, ex.tiled_over(Domain{0, 0, 2, 2}, {0.37, 0.61}).mapped_to(Domain{}), 0.5));
    // A rectangle of cut tiles: 2.6 x 2.3 exemplar windows.
    CHECK(periodic(ex, ex.tiled_over(Domain{0, 0, 2.6, 2.3}, {0.2, 0.7}), 1.0));
  }
}

TEST_CASE("periodicity: independent realizations are not periodic, a jittered grid of another seed included", "[scorecard]") {
  // Jittered grids whose cells line up with the exemplar's period: 10 x 10 cells per exemplar
  // window at full jitter, and 4 x 4 at jitter 0.3, whose Bragg peaks stand on the harmonics 4
  // and 8 (a mean over the harmonics would see them; the median does not).
  CHECK_FALSE(periodic(jittered_grid_points(100, 1), jittered_grid_points(400, 2, Domain{0, 0, 2, 2}), 1.0));
  CHECK_FALSE(periodic(jittered_grid_points(16, 1, Domain{}, 0.3), jittered_grid_points(64, 2, Domain{0, 0, 2, 2}, 0.3), 1.0));
  CHECK_FALSE(periodic(poisson_disk_points(100, 5), poisson_disk_points(400, 6, Domain{0, 0, 2, 2}), 1.0));
  CHECK_FALSE(periodic(uniform_points(100, 7), uniform_points(400, 8, Domain{0, 0, 2, 2}), 1.0));
}

TEST_CASE("periodicity: options out of range are refused; one copy does not repeat", "[scorecard]") {
  PeriodicityOptions o;
  o.harmonics = 0;
  CHECK_THROWS_WITH(check_periodicity_options(o), Catch::Contains("--periodicity-harmonics"));
  o = {};
  o.periodic_ratio = 1;
  CHECK_THROWS_WITH(check_periodicity_options(o), Catch::Contains("--periodic-ratio"));
  // The exemplar shifted on its torus, one period: a copy (the novelty line's) but no repeat.
  const PointSet ex = uniform_points(100, 9);
  CHECK_FALSE(periodic(ex, ex.tiled_over(Domain{0, 0, 1, 1}, {0.3, 0.3}), 1.0));
  CHECK(periodicity_report(ex, uniform_points(1, 10), 1.0, PeriodicityOptions{})["periodic"].is_null());
}

TEST_CASE("scorecard: the periodicity and border lines in eval's JSON, its table and gather's values", "[scorecard]") {
  const PointSet ex = poisson_disk_points(100, 11);
  const nlohmann::json r = evaluate(ex, ex.tiled_over(Domain{0, 0, 2, 2}, {0.4, 0.1}), scorecard_only());
  const auto& sc = r["scorecard"];
  REQUIRE(sc.contains("periodicity"));
  CHECK(sc["periodicity"]["periodic"] == true);
  CHECK(sc["periodicity"]["ratio"].get<double>() >= sc["periodicity"]["periodic_ratio"].get<double>());
  REQUIRE(sc.contains("border"));
  CHECK(sc["border"]["output"] == r["output"]["border_profile"]["over_uniform"]);
  CHECK(sc["border"]["band"].size() == 4);
  const std::string text = format_evaluation(r);
  CHECK_THAT(text, Catch::Contains("periodicity") && Catch::Contains("PERIODIC (periodic from 3)"));
  CHECK_THAT(text, Catch::Contains("border      over uniform within 0.5, 1, 2, 4 % of the shorter side: output"));
  double ratio = -1, flag = -1;
  for (const auto& [name, value] : metric_values(r, "metrics.json")) {
    if (name == "all/periodicity_ratio") ratio = value;
    if (name == "all/periodic") flag = value;
  }
  CHECK(ratio == sc["periodicity"]["ratio"].get<double>());
  CHECK(flag == 1.0);
  // A fresh pattern's line says so.
  const nlohmann::json fresh = evaluate(ex, poisson_disk_points(400, 12, Domain{0, 0, 2, 2}), scorecard_only());
  CHECK(fresh["scorecard"]["periodicity"]["periodic"] == false);
  CHECK_THAT(format_evaluation(fresh), Catch::Contains("no repeat (periodic from 3)"));
}
