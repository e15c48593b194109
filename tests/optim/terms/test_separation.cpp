// The separation term (method.terms.separation, not in the paper): thresholds from the exemplar's
// closest pairs per class pair and from disk radii, torus distances, gradient direction, and
// its effect inside a synthesis.
#include <catch2/catch.hpp>

#include "core/generators/lattices.hpp"
#include "optim/method/method.hpp"
#include "optim/terms/separation_term.hpp"

using namespace ppsynth;

namespace {

PointSet points(const std::vector<Vec2>& p, const std::vector<int>& cls) {
  PointSet ps;
  for (size_t i = 0; i < p.size(); ++i) ps.add(p[i], cls[i]);
  return ps;
}

torch::Tensor xy(const PointSet& ps) {
  auto t = torch::zeros({static_cast<int64_t>(ps.size()), 2});
  for (size_t i = 0; i < ps.size(); ++i) t[i][0] = ps[i].x, t[i][1] = ps[i].y;
  return t;
}

}  // namespace

TEST_CASE("Closest exemplar distance per class pair", "[optim][separation]") {
  auto ex = points({{0.1, 0.1}, {0.4, 0.1}, {0.1, 0.3}, {0.9, 0.9}}, {0, 0, 1, 2});
  auto d = class_pair_min_distance(ex);
  REQUIRE(d.size() == 3);
  CHECK(d[0][0] == Approx(0.3));
  CHECK(d[0][1] == Approx(0.2));
  CHECK(d[1][0] == Approx(0.2));
  CHECK(d[1][1] == 0);  // one point of class 1: no pair, no term
  CHECK(d[0][2] == Approx(std::hypot(0.5, 0.8)));
}

TEST_CASE("Separation term: torus distance, threshold, gradient apart", "[optim][separation]") {
  // Exemplar closest pair 0.2 -> output threshold 0.9 * 0.2 / 2 = 0.09.
  auto ex = points({{0.2, 0.5}, {0.4, 0.5}}, {0, 0});
  SECTION("a pair closer than the threshold is pushed apart") {
    auto out = points({{0.50, 0.5}, {0.55, 0.5}}, {0, 0});
    SeparationTerm term(ex, out, {0, 1}, {}, 2, 0.9);
    auto pos = xy(out).set_requires_grad(true);
    auto p = term(pos, torch::Tensor());
    CHECK(p.item<double>() == Approx(std::pow(1 - 0.05 / 0.09, 2)).epsilon(1e-4));
    p.backward();
    auto g = pos.grad();
    CHECK(g[0][0].item<double>() > 0);  // descending moves point 0 left, point 1 right
    CHECK(g[1][0].item<double>() < 0);
  }
  SECTION("farther than the threshold: no penalty") {
    auto out = points({{0.50, 0.5}, {0.60, 0.5}}, {0, 0});
    SeparationTerm term(ex, out, {0, 1}, {}, 2, 0.9);
    CHECK(term(xy(out), torch::Tensor()).item<double>() == 0);
  }
  SECTION("across the seam of the torus") {
    auto out = points({{0.01, 0.5}, {0.99, 0.5}}, {0, 0});
    SeparationTerm term(ex, out, {0, 1}, {}, 2, 0.9);
    CHECK(term(xy(out), torch::Tensor()).item<double>() == Approx(std::pow(1 - 0.02 / 0.09, 2)).epsilon(1e-4));
  }
  SECTION("frozen points count, with their class pair's threshold") {
    auto ex2 = points({{0.2, 0.5}, {0.4, 0.5}, {0.2, 0.8}}, {0, 0, 1});  // d(0,1) = 0.3
    auto out = points({{0.5, 0.5}, {0.5, 0.6}}, {0, 1});                  // moving: class 1
    SeparationTerm term(ex2, out, {1}, {0}, 2, 1.0);                      // threshold 0.15
    auto moving = xy(out.subset({1})), frozen = xy(out.subset({0}));
    CHECK(term(moving, frozen).item<double>() == Approx(std::pow(1 - 0.1 / 0.15, 2)).epsilon(1e-4));
  }
}

TEST_CASE("Separation term in a window: exemplar units over the grid's side, plane distances", "[optim][separation][windows]") {
  // A rectangle output is in exemplar units; a window's positions are (p - corner) / side.
  // Exemplar closest pair 0.2 -> threshold 0.9 * 0.2 / side in the window's coordinates.
  auto ex = points({{0.2, 0.5}, {0.4, 0.5}}, {0, 0});
  const double side = 1.5;
  SECTION("a pair closer than the threshold, in exemplar units") {
    auto out = points({{1.0, 1.0}, {1.15, 1.0}}, {0, 0});  // 0.15 apart: inside 0.18
    SeparationTerm term(ex, out, {0, 1}, {}, 2, 0.9, torch::kCPU, side);
    auto local = xy(out) / side;
    CHECK(term(local, torch::Tensor()).item<double>() == Approx(std::pow(1 - 0.15 / 0.18, 2)).epsilon(1e-4));
  }
  SECTION("no wrap: opposite edges of the grid are far apart") {
    auto out = points({{0.01, 0.75}, {1.49, 0.75}}, {0, 0});
    SeparationTerm term(ex, out, {0, 1}, {}, 2, 0.9, torch::kCPU, side);
    CHECK(term(xy(out) / side, torch::Tensor()).item<double>() == 0);
  }
  SECTION("disk radii in exemplar units, over the side too") {
    PointSet exd, outd;
    exd.add_attribute("radius");
    outd.add_attribute("radius");
    exd.add({0.2, 0.5}, 0, {0.01});
    exd.add({0.3, 0.5}, 0, {0.01});  // spacing threshold 0.09
    outd.add({1.0, 1.0}, 0, {0.1});
    outd.add({1.19, 1.0}, 0, {0.1});  // 0.19 apart: inside r_i + r_j = 0.2
    SeparationTerm term(exd, outd, {0, 1}, {}, 2, 0.9, torch::kCPU, side);
    CHECK(term(xy(outd) / side, torch::Tensor()).item<double>() == Approx(std::pow(1 - 0.19 / 0.2, 2)).epsilon(1e-3));
  }
}

TEST_CASE("Separation term: disks are kept apart by their radii", "[optim][separation]") {
  PointSet ex, out;
  ex.add_attribute("radius");
  out.add_attribute("radius");
  ex.add({0.2, 0.5}, 0, {0.02});
  ex.add({0.6, 0.5}, 0, {0.02});  // spacing threshold 0.9 * 0.4 / 2 = 0.18
  out.add({0.5, 0.5}, 0, {0.1});
  out.add({0.69, 0.5}, 0, {0.1});  // 0.19 apart: beyond the spacing, inside r_i + r_j = 0.2
  SeparationTerm term(ex, out, {0, 1}, {}, 2, 0.9);
  CHECK(term(xy(out), torch::Tensor()).item<double>() == Approx(std::pow(1 - 0.19 / 0.2, 2)).epsilon(1e-3));
}

TEST_CASE("Separation in a synthesis: adds to the loss, bad values name the key", "[optim][separation][synthesis]") {
  auto ex = jittered_grid_points(16, 5);
  struct FirstLoss : SynthesisObserver {
    double first = -1;
    void on_iteration(const ProgressEvent& e) override {
      if (first < 0) first = e.loss;
    }
  };
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 4;
  auto run = [&](json extra, FirstLoss& seen) {
    json spec = {{"type", "gabor"}};
    spec.update(extra);
    ctx.observers = {&seen};
    return MethodRegistry::instance().create(spec, "method")->synthesize(ex, ctx);
  };
  FirstLoss plain, separated;
  run(json::object(), plain);
  // fraction 2: twice the exemplar's closest distance (/ u) is more than a Poisson-disk
  // initialization's spacing, so the first evaluation already pays for some pairs.
  run(json{{"terms", {{"separation", {{"weight", 1.0}, {"fraction", 2.0}}}}}}, separated);
  CHECK(separated.first > plain.first);
  FirstLoss unused;
  CHECK_THROWS_WITH(run(json{{"terms", {{"separation", {{"weight", -1.0}}}}}}, unused), Catch::Contains("separation.weight"));
  CHECK_THROWS_WITH(run(json{{"terms", {{"separation", {{"weight", 1.0}, {"fraction", 0.0}}}}}}, unused), Catch::Contains("separation.fraction"));
  CHECK_THROWS_WITH(run(json{{"terms", {{"separation", {{"radius", 0.1}}}}}}, unused), Catch::Contains("separation"));
}
