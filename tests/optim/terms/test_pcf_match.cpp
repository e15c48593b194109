// The PCF-matching term (method.terms.pcf_match, not in the paper): its curves are core's torus
// estimator against core's exemplar estimator, it skips curves with nothing to say, descending
// it brings a pattern's PCF to the exemplar's, and inside a synthesis it acts and names its
// keys.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/generators/lattices.hpp"
#include "core/generators/uniform.hpp"
#include "core/metrics/pcf.hpp"
#include "optim/method/method.hpp"
#include "optim/terms/pcf_match_term.hpp"

using namespace ppsynth;

namespace {

torch::Tensor xy(const PointSet& ps) {
  auto t = torch::zeros({static_cast<int64_t>(ps.size()), 2});
  for (size_t i = 0; i < ps.size(); ++i) t[i][0] = ps[i].x, t[i][1] = ps[i].y;
  return t;
}

// Two classes: `a` points of class 0 then `b` of class 1.
PointSet two_classes(const PointSet& a, const PointSet& b) {
  PointSet ps;
  for (size_t i = 0; i < a.size(); ++i) ps.add(a[i], 0);
  for (size_t i = 0; i < b.size(); ++i) ps.add(b[i], 1);
  return ps;
}

std::vector<size_t> range(size_t from, size_t to) {
  std::vector<size_t> r;
  for (size_t i = from; i < to; ++i) r.push_back(i);
  return r;
}

// mean over the bins within half the torus of (g_out - g_ex)^2, from core's estimators.
double expected_mse(const Curve& ex, const Curve& out, double r_max_out) {
  double s = 0;
  int n = 0;
  for (size_t b = 0; b < ex.r.size() && ex.r[b] * r_max_out <= 0.5; ++b, ++n) s += std::pow(out.g[b] - ex.g[b], 2);
  return s / n;
}

}  // namespace

TEST_CASE("PCF match term: core's estimators, auto and cross", "[optim][pcf_match]") {
  const auto ex = two_classes(uniform_points(12, 1), uniform_points(8, 2));
  const auto out = two_classes(uniform_points(48, 3), uniform_points(32, 4));
  PointSet out_torus = out;
  out_torus.set_domain(Domain{0, 0, 1, 1, true});
  const auto ex0 = ex.subset_class(0), ex1 = ex.subset_class(1);

  SECTION("first class: its own PCF on the torus against the exemplar class's") {
    PcfMatchTerm term(ex, out, range(0, 48), {}, 2, true);
    REQUIRE(term.curves() == 1);
    PcfOptions o;
    o.r_max = pcf_unit(48);
    const double want = expected_mse(pcf(ex0), pcf(out_torus.subset_class(0), o), o.r_max);
    CHECK(term(xy(out.subset_class(0)), torch::Tensor()).item<double>() == Approx(want).epsilon(2e-3));
  }
  SECTION("second class: its PCF plus the cross-PCF to the frozen first class") {
    PcfMatchTerm with_cross(ex, out, range(48, 80), range(0, 48), 2, true);
    PcfMatchTerm auto_only(ex, out, range(48, 80), range(0, 48), 2, false);
    REQUIRE(with_cross.curves() == 2);
    REQUIRE(auto_only.curves() == 1);
    PcfOptions o, oc;
    o.r_max = pcf_unit(32);
    oc.r_max = pcf_unit(80);
    const double want_auto = expected_mse(pcf(ex1), pcf(out_torus.subset_class(1), o), o.r_max);
    const double want_cross =
        expected_mse(cross_pcf(ex1, ex0), cross_pcf(out_torus.subset_class(1), out_torus.subset_class(0), oc), oc.r_max);
    const auto moving = xy(out.subset_class(1)), frozen = xy(out.subset_class(0));
    CHECK(auto_only(moving, frozen).item<double>() == Approx(want_auto).epsilon(2e-3));
    CHECK(with_cross(moving, frozen).item<double>() == Approx(want_auto + want_cross).epsilon(2e-3));
  }
  SECTION("a class of one exemplar point has no PCF to match") {
    PointSet ex_single = ex0;
    ex_single.add({0.5, 0.5}, 1);
    PcfMatchTerm term(ex_single, out, range(48, 52), {}, 2, true);  // 4 moving points of class 1
    CHECK(term.curves() == 0);
    CHECK(term(xy(out.subset(range(48, 52))), torch::Tensor()).item<double>() == 0);
  }
}

TEST_CASE("PCF match term: descending it brings the PCF to the exemplar's", "[optim][pcf_match]") {
  // A regular 5 x 5 grid exemplar; the output starts uniform (clumps and gaps) on the torus.
  PointSet ex = regular_grid_points(25, 1);
  PointSet out = uniform_points(100, 7);
  PcfMatchTerm term(ex, out, range(0, 100), {}, 2, true);
  auto pos = xy(out).set_requires_grad(true);
  torch::optim::Adam adam({pos}, torch::optim::AdamOptions(2e-3));
  const double start = term(pos, torch::Tensor()).item<double>();
  for (int it = 0; it < 150; ++it) {
    adam.zero_grad();
    auto l = term(pos, torch::Tensor());
    l.backward();
    adam.step();
  }
  const double end = term(pos, torch::Tensor()).item<double>();
  INFO("start " << start << " end " << end);
  CHECK(end < 0.3 * start);
  // The 10 x 10 grid it should become scores far better than where it started.
  PcfMatchTerm grid_term(ex, out, range(0, 100), {}, 2, true);
  CHECK(grid_term(xy(regular_grid_points(100, 1)), torch::Tensor()).item<double>() < 0.3 * start);
}

TEST_CASE("PCF match in a synthesis: moves the first class, bad values name the key", "[optim][pcf_match][synthesis]") {
  auto ex = jittered_grid_points(16, 5);
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 4;
  auto run = [&](json extra) {
    json spec = {{"type", "gabor"}};
    spec.update(extra);
    return MethodRegistry::instance().create(spec, "method")->synthesize(ex, ctx);
  };
  const auto plain = run(json::object());
  const auto matched = run(json{{"terms", {{"pcf_match", {{"weight", 1.0}}}}}});
  REQUIRE(plain.size() == matched.size());
  double moved = 0;
  for (size_t i = 0; i < plain.size(); ++i) moved += std::hypot(plain[i].x - matched[i].x, plain[i].y - matched[i].y);
  CHECK(moved > 1e-4);
  CHECK_THROWS_WITH(run(json{{"terms", {{"pcf_match", {{"weight", -1.0}}}}}}), Catch::Contains("pcf_match.weight"));
  CHECK_THROWS_WITH(run(json{{"terms", {{"pcf_match", {{"weight", 1.0}, {"cross", 1}}}}}}), Catch::Contains("pcf_match.cross"));
  CHECK_THROWS_WITH(run(json{{"terms", {{"pcf_match", {{"sigma", 0.1}}}}}}), Catch::Contains("pcf_match"));
}
