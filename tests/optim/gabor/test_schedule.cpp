#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/metrics/crops.hpp"
#include "core/metrics/patches.hpp"
#include "core/metrics/pcf.hpp"
#include "optim/steps/stopping_rule.hpp"
#include "optim/gabor/pipeline/gabor_pipeline.hpp"
#include "optim/gabor/settings/sigma_schedule.hpp"

using namespace ppsynth;

TEST_CASE("Sigma schedule: d/c1 down to d/c2, evenly spaced", "[optim]") {
  auto s = sigma_schedule(0.1, 1.0, 2.6, 4);
  REQUIRE(s.size() == 4);
  CHECK(s[0] == Approx(0.1));
  CHECK(s[3] == Approx(0.1 / 2.6));
  CHECK(s[1] - s[0] == Approx(s[2] - s[1]));
  // An exemplar without spacing; c1, c2 and the count are bounded where they are declared (test_gabor_options.cpp).
  CHECK_THROWS_AS(sigma_schedule(0.0, 1.0, 2.6), InputError);
}

namespace {

// The "loss" rule's verdict after the losses L (the last one from iteration L.size() - 1).
bool loss_rule_stops(StoppingRule& rule, const std::vector<double>& L) {
  std::vector<double> record;
  return rule.judge(StageView{L, static_cast<int>(L.size()) - 1, {}, true}, record).stop;
}

}  // namespace

TEST_CASE("Convergence rule as the published code checks it", "[optim]") {
  auto rule = StoppingRuleRegistry::instance().create(json{{"type", "loss"}}, "method.convergence");
  std::vector<double> L;
  // Fast decay then flat: fires at the first check after 100 iterations.
  for (int i = 0; i < 200; ++i) L.push_back(i < 10 ? 1.0 - 0.09 * i : 0.1);
  std::vector<double> prefix(L.begin(), L.begin() + 100);
  CHECK_FALSE(loss_rule_stops(*rule, prefix));  // not more than 100 yet
  std::vector<double> p111(L.begin(), L.begin() + 111);
  CHECK(loss_rule_stops(*rule, p111));
  std::vector<double> p112(L.begin(), L.begin() + 112);
  CHECK_FALSE(loss_rule_stops(*rule, p112));  // only every 10th iteration
  // Steady linear decrease: 100 of 110 iterations' worth of decrease is far above 1%.
  std::vector<double> lin;
  for (int i = 0; i < 111; ++i) lin.push_back(1.0 - 0.001 * i);
  CHECK_FALSE(loss_rule_stops(*rule, lin));
  CHECK_THROWS_WITH(StoppingRuleRegistry::instance().create(json{{"type", "loss"}, {"check_every", 0}}, "method.convergence"),
                    Catch::Contains("method.convergence.check_every"));
  CHECK_THROWS_WITH(StoppingRuleRegistry::instance().create(json{{"type", "loss"}, {"patience", 3}}, "method.convergence"),
                    Catch::Contains("method.convergence.patience"));
}

TEST_CASE("The pattern rule stops when the PCF stops improving, not while it improves", "[optim]") {
  // Exemplar: a jittered 8 x 8 grid. The "stage" moves a uniform pattern towards a 16 x 16
  // jittered grid on the torus (blend t), then holds it: the rule must wait while the PCF
  // improves and stop within one window of the hold.
  auto rule = StoppingRuleRegistry::instance().create(
      json{{"type", "pattern"}, {"window", 30}, {"check_every", 10}, {"threshold", 0.02}, {"min_iterations", 0}},
      "method.convergence");
  auto jittered = [](int n, double amp, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    std::vector<Vec2> v;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) v.push_back({(i + 0.5 + amp * u(rng)) / n, (j + 0.5 + amp * u(rng)) / n});
    return v;
  };
  PointSet ex;
  for (auto p : jittered(8, 0.3, 1)) ex.add(p);
  rule->begin_stage(ex, -1);
  const auto goal = jittered(16, 0.3, 2), start = jittered(16, 2.0, 3);  // start: nearly uniform
  std::vector<double> losses, record;
  int stopped_at = -1;
  const int hold_from = 150;
  for (int it = 0; it < 400 && stopped_at < 0; ++it) {
    losses.push_back(1.0 / (it + 1));  // a loss that keeps falling: only the pattern may stop it
    const double t = std::min(1.0, it / double(hold_from));
    auto points = [&] {
      PointSet ps;
      for (size_t i = 0; i < goal.size(); ++i) {
        Vec2 p{start[i].x + t * (goal[i].x - start[i].x), start[i].y + t * (goal[i].y - start[i].y)};
        ps.add({p.x - std::floor(p.x), p.y - std::floor(p.y)});
      }
      return ps;
    };
    const StopVerdict v = rule->judge(StageView{losses, it, points, true}, record);
    CHECK_FALSE(v.best);  // end_on "last" (the default) never asks to keep an iterate
    if (v.stop) stopped_at = it;
  }
  INFO("stopped at iteration " << stopped_at << ", " << record.size() << " checks");
  CHECK(stopped_at >= hold_from);
  CHECK(stopped_at <= hold_from + 30 + 10);
  CHECK(record.front() > 2 * record.back());  // it watched the pattern improve
}

TEST_CASE("The pattern rule with end_on best marks each new best check and no other iteration", "[optim]") {
  // A pattern that walks from nearly uniform to the exemplar's kind (a jittered grid) and
  // back: the checks improve, then worsen. The marked iterates are exactly the checks that
  // beat every earlier one, so the last mark is the check nearest the turn.
  auto rule = StoppingRuleRegistry::instance().create(
      json{{"type", "pattern"}, {"window", 1000}, {"check_every", 10}, {"min_iterations", 0}, {"end_on", "best"}},
      "method.convergence");
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0, 1);
  PointSet ex, goal, start;
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) {
      ex.add({(i + 0.4 + 0.2 * u(rng)) / 12, (j + 0.4 + 0.2 * u(rng)) / 12});
      goal.add({(i + 0.4 + 0.2 * u(rng)) / 12, (j + 0.4 + 0.2 * u(rng)) / 12});
      start.add({u(rng), u(rng)});
    }
  rule->begin_stage(ex, -1);
  std::vector<double> losses, record;
  std::vector<int> marked;
  const int turn = 100;
  for (int it = 0; it < 200; ++it) {
    losses.push_back(1.0);
    const double t = 1.0 - std::abs(it - turn) / double(turn);  // 0 -> 1 at the turn -> 0
    auto points = [&] {
      PointSet ps;
      for (size_t i = 0; i < goal.size(); ++i)
        ps.add({start[i].x + t * (goal[i].x - start[i].x),
                start[i].y + t * (goal[i].y - start[i].y)});
      return ps;
    };
    const StopVerdict v = rule->judge(StageView{losses, it, points, true}, record);
    CHECK_FALSE(v.stop);  // the window is longer than the stage
    if (v.best) marked.push_back(it);
  }
  // The record pairs each check's PCF MSE as optimized (the torus: the stop watches it) with
  // the one as seen (the plane square, as the evaluation measures: the best is chosen by it).
  REQUIRE(record.size() == 40u);
  auto seen = [&](int it) { return record[2 * static_cast<size_t>((it - 9) / 10) + 1]; };
  REQUIRE_FALSE(marked.empty());
  int best = 9;
  for (int it = 9; it < 200; it += 10)
    if (seen(it) < seen(best)) best = it;
  CHECK(marked.back() == best);  // the stage's best check is the last one marked
  CHECK(std::abs(marked.back() - turn) <= 20);
  for (size_t k = 1; k < marked.size(); ++k) CHECK(seen(marked[k]) < seen(marked[k - 1]));
  {  // the last check (iteration 199) by hand: torus first, plane second
    const double t = 1.0 - std::abs(199 - turn) / double(turn);
    PointSet ps;
    for (size_t i = 0; i < goal.size(); ++i)
      ps.add({start[i].x + t * (goal[i].x - start[i].x), start[i].y + t * (goal[i].y - start[i].y)});
    PcfOptions torus;
    torus.periodic = true;
    CHECK(record[38] == Approx(curve_mse(pcf(ps, torus), pcf(ex))).epsilon(1e-12));
    CHECK(record[39] == Approx(curve_mse(pcf(ps), pcf(ex))).epsilon(1e-12));
    CHECK(record[38] != record[39]);
  }

  // The stage's start (iteration -1) is a candidate too: a stage that only worsens the
  // pattern keeps its start, and no later check is marked.
  rule->begin_stage(ex, -1);
  std::vector<double> worse_record;
  int marks = 0;
  bool start_marked = false;
  for (int it = -1; it < 60; ++it) {
    const double t = 1.0 - (it + 1) / 60.0;  // from the goal towards uniform
    auto points = [&] {
      PointSet ps;
      for (size_t i = 0; i < goal.size(); ++i)
        ps.add({start[i].x + t * (goal[i].x - start[i].x), start[i].y + t * (goal[i].y - start[i].y)});
      return ps;
    };
    const StopVerdict v = rule->judge(StageView{losses, it, points, true}, worse_record);
    if (v.best) (it < 0 ? start_marked = true : ++marks);
  }
  CHECK(start_marked);
  CHECK(marks == 0);
  CHECK(worse_record.size() == 14u);  // the start and six checks, each as optimized and as seen
  // Ending on the last iterate, the start is not measured (the stopping window is unchanged).
  auto last_rule = StoppingRuleRegistry::instance().create(json{{"type", "pattern"}}, "method.convergence");
  last_rule->begin_stage(ex, -1);
  std::vector<double> last_record;
  CHECK_FALSE(last_rule->judge(StageView{losses, -1, [&] { return goal; }, true}, last_record).best);
  CHECK(last_record.empty());
  CHECK_THROWS_WITH(StoppingRuleRegistry::instance().create(json{{"type", "pattern"}, {"end_on", "first"}}, "method.convergence"),
                    Catch::Contains("method.convergence.end_on"));
}

TEST_CASE("Pattern rule, best_by crops: the best is judged on exemplar-sized crops, not the whole rectangle", "[optim]") {
  auto rule = StoppingRuleRegistry::instance().create(
      json{{"type", "pattern"}, {"window", 1000}, {"check_every", 1}, {"min_iterations", 0}, {"end_on", "best"},
           {"best_by", "crops"}},
      "method.convergence");
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  PointSet ex;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) ex.add({(i + 0.3 + 0.4 * u(rng)) / 8, (j + 0.3 + 0.4 * u(rng)) / 8});
  rule->begin_stage(ex, -1);
  // Iterates on the paper's u = 2 square (zoom 1/2): jittered grids of 256 points, more or
  // less jittered, some with points parked on the border.
  std::vector<PointSet> iterates;
  for (int k = 0; k < 12; ++k) {
    PointSet ps;
    const double jitter = 0.2 + 0.6 * u(rng);
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        Vec2 p{(i + 0.5 + jitter * (u(rng) - 0.5)) / 16, (j + 0.5 + jitter * (u(rng) - 0.5)) / 16};
        if (k % 3 == 0 && (i == 0 || j == 0)) p = {i == 0 ? 0.0 : p.x, j == 0 ? 0.0 : p.y};  // parked
        ps.add(p);
      }
    iterates.push_back(ps);
  }
  // What the rule should see: 20 crops of half the square, at the rule's own places (seed
  // 7919), each on the unit square with the exemplar's r_max.
  PcfOptions o;
  o.r_max = pcf_unit(ex.size(), 1.0);
  const Curve target = pcf(ex, o);
  auto by_crops = [&](const PointSet& ps) {
    const CropPlan plan = plan_crops(ex, ps, 20, 7919, 0.5);
    double sum = 0;
    for (const PointSet& patch : cut_patches(ps, plan.windows)) sum += curve_mse(pcf(patch, o), target);
    return sum / 20;
  };
  std::vector<double> losses, record;
  double best = std::numeric_limits<double>::infinity();
  int differs = 0;
  for (int it = 0; it < static_cast<int>(iterates.size()); ++it) {
    losses.push_back(1.0);
    const StopVerdict v = rule->judge(StageView{losses, it, [&] { return iterates[it]; }, true, 0.5}, record);
    const double expected = by_crops(iterates[it]);
    CHECK(record.back() == Approx(expected).epsilon(1e-12));
    CHECK(v.best == (expected < best));
    best = std::min(best, expected);
    differs += std::abs(record.back() - curve_mse(pcf(iterates[it]), pcf(ex))) > 1e-6;
  }
  CHECK(differs == static_cast<int>(iterates.size()));  // not the whole rectangle's value
  CHECK_THROWS_WITH(StoppingRuleRegistry::instance().create(json{{"type", "pattern"}, {"best_by", "quadrants"}}, "method.convergence"),
                    Catch::Contains("method.convergence.best_by"));
}

TEST_CASE("Toroidal wrap as published", "[optim]") {
  auto x = torch::tensor({-0.25, 0.5, 1.25, 2.5, -1.5});
  auto w = wrap_unit(x);
  CHECK(w[0].item<float>() == Approx(0.75));
  CHECK(w[1].item<float>() == Approx(0.5));
  CHECK(w[2].item<float>() == Approx(0.25));
  CHECK(w[3].item<float>() == Approx(0.5));
  CHECK(w[4].item<float>() == Approx(0.5));
  auto p = x.clone().set_requires_grad(true);
  wrap_unit(p).sum().backward();
  CHECK(torch::equal(p.grad(), torch::ones_like(x)));
}

TEST_CASE("Pattern rule, rows: a stage moving one class among others is judged by that class's own and cross PCFs",
          "[optim]") {
  // Two classes of jittered grids, shifted against each other; the iterate: the exemplar's
  // class 0 (frozen) and a class 1 of its own draw, as a stage moving class 1 sees them.
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(0, 1);
  auto grid = [&](PointSet& ps, int cls, double shift, double jitter) {
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i)
        ps.add({(i + shift + jitter * (u(rng) - 0.5)) / 10, (j + shift + jitter * (u(rng) - 0.5)) / 10}, cls);
  };
  PointSet ex, it;
  grid(ex, 0, 0.25, 0.2);
  grid(ex, 1, 0.75, 0.2);
  for (size_t i = 0; i < ex.size(); ++i)
    if (ex.cls(i) == 0) it.add(ex[i], 0);
  grid(it, 1, 0.5, 0.9);
  const PointSet ex0 = ex.subset_class(0), ex1 = ex.subset_class(1), it0 = it.subset_class(0), it1 = it.subset_class(1);
  const double own = curve_mse(pcf(it1), pcf(ex1)), cross = curve_mse(cross_pcf(it1, it0), cross_pcf(ex1, ex0));
  const double pooled = curve_mse(pcf(it), pcf(ex));
  auto first_check = [&](const json& rows, int moving_class, const PointSet& exemplar, const PointSet& iterate) {
    auto rule = StoppingRuleRegistry::instance().create(
        json{{"type", "pattern"}, {"check_every", 1}, {"min_iterations", 0}, {"rows", rows}}, "method.convergence");
    rule->begin_stage(exemplar, moving_class);
    std::vector<double> losses{1.0}, record;
    rule->judge(StageView{losses, 0, [&] { return iterate; }, false}, record);
    REQUIRE(record.size() == 1u);
    return record[0];
  };
  // The default: the moving class's own PCF and its cross PCF with the frozen class, averaged.
  CHECK(first_check("moving_class", 1, ex, it) == Approx((own + cross) / 2).epsilon(1e-12));
  CHECK(first_check("all", 1, ex, it) == Approx(pooled).epsilon(1e-12));
  CHECK(own != Approx(pooled).epsilon(0.01));
  // One class in play, or no moving class named: the points as one pattern either way.
  CHECK(first_check("moving_class", 0, ex0, it0) == first_check("all", 0, ex0, it0));
  CHECK(first_check("moving_class", -1, ex, it) == Approx(pooled).epsilon(1e-12));
  // A window holding one point of the moving class: its rows cannot be measured, the pooled PCF can.
  PointSet sparse = it0;
  sparse.add({0.5, 0.5}, 1);
  CHECK(first_check("moving_class", 1, ex, sparse) == Approx(curve_mse(pcf(sparse), pcf(ex))).epsilon(1e-12));
  CHECK_THROWS_WITH(StoppingRuleRegistry::instance().create(json{{"type", "pattern"}, {"rows", "pooled"}}, "method.convergence"),
                    Catch::Contains("method.convergence.rows"));
}
