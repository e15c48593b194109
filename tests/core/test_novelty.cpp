// The scorecard's estimators (core/metrics/novelty.hpp, close_pairs.hpp): a tiled copy of the
// exemplar scores as a copy, seams and all; an independent realization of the process does
// not; two translates are flagged as such; close pairs on a pattern counted by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/error.hpp"
#include "core/generators/poisson_disk.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/close_pairs.hpp"
#include "core/metrics/evaluation.hpp"
#include "core/metrics/novelty.hpp"

using namespace ppsynth;

namespace {

// The exemplar (unit square) tiled u x u on the unit square and shifted on the torus, as
// the tiled_copy method makes it: its seams are the exemplar's own wrap-around.
PointSet tiled(const PointSet& ex, int u, Vec2 shift) {
  PointSet out(Domain{});
  auto wrap = [](double v) { return v - std::floor(v); };
  for (int a = 0; a < u; ++a)
    for (int b = 0; b < u; ++b)
      for (size_t i = 0; i < ex.size(); ++i)
        out.add({wrap((ex[i].x + a) / u + shift.x), wrap((ex[i].y + b) / u + shift.y)}, ex.cls(i));
  return out;
}

PointSet two_classes(PointSet ps) {
  for (size_t i = 0; i < ps.size(); ++i) ps.set_cls(i, static_cast<int>(i % 2));
  return ps;
}

}  // namespace

TEST_CASE("novelty: a tiled copy of the exemplar is a copy, seams included", "[novelty]") {
  for (const bool classes : {false, true}) {
    INFO("two classes: " << classes);
    PointSet ex = uniform_points(150, 7);
    if (classes) ex = two_classes(ex);
    const PointSet out = tiled(ex, 2, {0.37, 0.61});  // seams cross the output's middle
    const auto j = novelty_report(ex, out, 0.5, NoveltyOptions{});
    CHECK(j["scored"].get<size_t>() > 300);
    CHECK(j["share"].get<double>() == 1.0);
    CHECK(j["copy"].get<bool>());
    CHECK(j["closest"].get<double>() < 1e-9);
  }
}

TEST_CASE("novelty: independent realizations of the process, and CSR, are new", "[novelty]") {
  // Regular patterns are the hard case: their neighbourhoods look alike.
  const PointSet pd = poisson_disk_points(200, 11);
  const PointSet pd_other = poisson_disk_points(800, 12);
  const auto a = novelty_report(pd, pd_other, 0.5, NoveltyOptions{});
  CHECK(a["scored"].get<size_t>() > 400);
  CHECK(a["matched"].get<size_t>() == 0);
  CHECK_FALSE(a["copy"].get<bool>());
  const auto b = novelty_report(uniform_points(200, 13), uniform_points(800, 14), 0.5, NoveltyOptions{});
  CHECK(b["matched"].get<size_t>() == 0);
  CHECK_FALSE(b["copy"].get<bool>());
  // The other classes' copy: positions copied, labels not, is not a copy of the labelled pattern.
  const PointSet ex = two_classes(uniform_points(150, 7));
  PointSet relabelled = tiled(ex, 2, {0.37, 0.61});
  for (size_t i = 0; i < relabelled.size(); ++i) relabelled.set_cls(i, 1 - relabelled.cls(i));
  CHECK(novelty_report(ex, relabelled, 0.5, NoveltyOptions{})["share"].get<double>() == 0.0);
}

TEST_CASE("novelty: a copy thinned or padded is not a whole-neighbourhood match", "[novelty]") {
  const PointSet ex = poisson_disk_points(150, 21);
  const PointSet copy = tiled(ex, 2, {0.2, 0.3});
  PointSet thinned(copy.domain());
  for (size_t i = 0; i < copy.size(); i += 2) thinned.add(copy[i]);
  CHECK(novelty_report(ex, thinned, 0.5, NoveltyOptions{})["share"].get<double>() < 0.05);
}

TEST_CASE("diversity: two translates of one pattern are flagged; independent draws are not", "[novelty]") {
  const PointSet ex = poisson_disk_points(150, 31);
  const PointSet one = tiled(ex, 2, {0.1, 0.2}), two = tiled(ex, 2, {0.55, 0.8});
  const auto same = diversity_report(ex, one, two, 0.5, NoveltyOptions{});
  CHECK(same["copy"].get<bool>());
  CHECK(same["share"].get<double>() > 0.5);  // the other's edge cuts some neighbourhoods
  const auto apart = diversity_report(ex, one, poisson_disk_points(600, 32), 0.5, NoveltyOptions{});
  CHECK(apart["matched"].get<size_t>() == 0);
  CHECK_FALSE(apart["copy"].get<bool>());
}

TEST_CASE("novelty: options out of range are refused naming eval's flag", "[novelty]") {
  NoveltyOptions o;
  o.k = 0;
  CHECK_THROWS_WITH(check_novelty_options(o), Catch::Contains("--novelty-k"));
  o = {};
  o.tolerance = 0;
  CHECK_THROWS_WITH(check_novelty_options(o), Catch::Contains("--novelty-tolerance"));
  o = {};
  o.copy_share = 1.5;
  CHECK_THROWS_WITH(check_novelty_options(o), Catch::Contains("--novelty-copy-share"));
  // Too few output points for one neighbourhood: nothing scored, no flag either way.
  const auto j = novelty_report(uniform_points(20, 1), uniform_points(5, 2), 1, NoveltyOptions{});
  CHECK(j["share"].is_null());
  CHECK(j["copy"].is_null());
}

TEST_CASE("close pairs: counted by hand on a tiny pattern", "[novelty]") {
  // Exemplar on the unit square: class 0 at (0.1, 0.1), (0.3, 0.1) (closest 0.2), class 1 at
  // (0.1, 0.6), (0.5, 0.6) (closest 0.4); across, (0.1, 0.1)-(0.1, 0.6) = 0.5 is the closest.
  PointSet ex(Domain{});
  ex.add({0.1, 0.1}, 0);
  ex.add({0.3, 0.1}, 0);
  ex.add({0.1, 0.6}, 1);
  ex.add({0.5, 0.6}, 1);
  // Output on [0, 2]^2 at zoom 2; in exemplar units (halved): class 0 at (0.2, 0.2),
  // (0.3, 0.2), (0.8, 0.8): one pair 0.1 apart (below 0.2); class 1 at (0.5, 0.5), (0.8, 0.5):
  // 0.3 apart (below 0.4); across, below 0.5: (0.2, 0.2)-(0.5, 0.5) 0.424, (0.3, 0.2)-(0.5, 0.5)
  // 0.361, (0.8, 0.8)-(0.8, 0.5) 0.3, (0.8, 0.8)-(0.5, 0.5) 0.424: 4 pairs, every point in one.
  PointSet out(Domain{0, 0, 2, 2});
  out.add({0.4, 0.4}, 0);
  out.add({0.6, 0.4}, 0);
  out.add({1.6, 1.6}, 0);
  out.add({1.0, 1.0}, 1);
  out.add({1.6, 1.0}, 1);
  const auto rows = close_pairs_report(ex, out, 2.0)["rows"];
  REQUIRE(rows.size() == 4);  // all, class 0, class 1, pair 0-1
  const auto& all = rows[0];
  CHECK(all["exemplar_min"].get<double>() == Approx(0.2));
  CHECK(all["output_min"].get<double>() == Approx(0.1));
  // Pairs below 0.2 among all 5 points: only (0.4, 0.4)-(0.6, 0.4): its 2 points of 5.
  CHECK(all["pairs_below"].get<size_t>() == 1);
  CHECK(all["share_below"].get<double>() == Approx(0.4));
  // d_max = sqrt(2 / (sqrt(3) n)) on the unit square (n = 4): 0.5373.
  CHECK(all["exemplar_normalized"].get<double>() == Approx(0.2 / std::sqrt(2 / (std::sqrt(3.0) * 4))));
  // The output in exemplar units is the unit square with 5 points.
  CHECK(all["output_normalized"].get<double>() == Approx(0.1 / std::sqrt(2 / (std::sqrt(3.0) * 5))));
  const auto& c0 = rows[1];
  CHECK(c0["class"] == 0);
  CHECK(c0["pairs_below"].get<size_t>() == 1);
  CHECK(c0["share_below"].get<double>() == Approx(2.0 / 3));
  const auto& c1 = rows[2];
  CHECK(c1["exemplar_min"].get<double>() == Approx(0.4));
  CHECK(c1["pairs_below"].get<size_t>() == 1);
  CHECK(c1["share_below"].get<double>() == Approx(1.0));
  const auto& pair = rows[3];
  CHECK(pair["row"] == "pair");
  CHECK(pair["exemplar_min"].get<double>() == Approx(0.5));
  CHECK(pair["output_min"].get<double>() == Approx(0.3));
  CHECK(pair["pairs_below"].get<size_t>() == 4);
  CHECK(pair["share_below"].get<double>() == Approx(1.0));
  // A pair as close as the exemplar's own is not below it: the exemplar against itself.
  for (const auto& row : close_pairs_report(ex, ex, 1.0)["rows"]) CHECK(row["pairs_below"].get<size_t>() == 0);
}

TEST_CASE("the scorecard is in evaluate()'s result, and off with scorecard = false", "[novelty]") {
  const PointSet ex = poisson_disk_points(100, 41);
  EvalOptions opt;
  opt.verdict = false;
  opt.second_order = false;
  const auto r = evaluate(ex, tiled(ex, 2, {0.3, 0.3}), opt);
  CHECK(r["scorecard"]["novelty"]["copy"].get<bool>());
  CHECK(r["scorecard"]["close_pairs"]["rows"].size() == 1);
  opt.scorecard = false;
  CHECK_FALSE(evaluate(ex, tiled(ex, 2, {0.3, 0.3}), opt).contains("scorecard"));
}
