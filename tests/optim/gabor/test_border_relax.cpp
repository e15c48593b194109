// method.border_relax (optim/gabor/stages/border_relax/border_relax_stage.hpp): after each class's sigma stages on the u x u
// torus, a stage that moves only that class's points within the band of the grid's edge, on
// the rolled grid. It must leave every other point where the stage found it, move the band,
// resume bit for bit, and be refused where there is no grid edge. By default ("auto") it runs
// wherever there is one; configs/runs keep the published border.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/config/config.hpp"
#include "core/metrics/border.hpp"
#include "core/metrics/nearest_neighbor.hpp"
#include "core/output_shape.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/gabor/stages/border_relax/border_relax_stage.hpp"
#include "optim/method/method.hpp"
#include "optim/run/run_config.hpp"
#include "tests/support/gabor_runs.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/small_exemplar.hpp"
#include "tests/support/stage_ends.hpp"

using namespace ppsynth;
using ppsynth::test::method_params;
using ppsynth::test::same_bits;
using ppsynth::test::StageEnds;

namespace {

// The relax's options as its kind resolved them from the settings' block (none asked: 0
// iterations).
BorderRelaxSettings relax_options(const GaborSettings& s) {
  for (const auto& kind : class_end_kinds(s))
    if (const auto* relax = dynamic_cast<const BorderRelaxStage*>(kind.get())) return relax->options();
  return {};
}

// parked 0: every class is relaxed, parked or not (tiny runs park less than the bound).
// after "class": each class's relax right after its sigma stages (the default "all": below).
// No revisit: the relax's stages are the only ones after the sigma stages.
json relaxed_method(int iterations, double separation = 1.0, double parked = 0) {
  return json{{"type", "gabor"},
              {"border_relax", {{"iterations", iterations}, {"band", 1.0}, {"separation", separation}, {"parked", parked}, {"after", "class"}}},
              {"revisit", {{"iterations", 0}}},
              {"quick", {{"res", 16}, {"channels", 4}, {"max_iterations", 5}, {"num_sigmas", 2}}}};
}

// A relax stage of class c, from `before` to `after`: checks that every point but class c's
// within `band` of the edge stayed bit for bit; adds the band's points and those that moved.
void check_band_relax(const PointSet& before, const PointSet& after, int c, double band, size_t& band_points, size_t& moved) {
  REQUIRE(before.size() == after.size());
  for (size_t i = 0; i < before.size(); ++i) {
    const Vec2 p = before[i];
    const bool in_band = p.x < band || p.x > 1 - band || p.y < band || p.y > 1 - band;
    if (before.cls(i) == c && in_band) {
      ++band_points;
      moved += p.x != after[i].x || p.y != after[i].y;
    } else {
      INFO("relax of class " << c << ", point " << i << " of class " << before.cls(i));
      CHECK(p.x == after[i].x);  // frozen: bit for bit where the stage found it
      CHECK(p.y == after[i].y);
    }
  }
}

}  // namespace

TEST_CASE("a border relax moves only its class's points near the grid's edge, after the class's sigmas", "[optim][border_relax]") {
  for (int classes : {1, 2}) {
    INFO(classes << " classes");
    const PointSet ex = test::small_exemplar(classes, false);
    const double band = mean_nn_distance(ex) / 2;  // 1 mean spacing of the u = 2 output
    auto method = MethodRegistry::instance().create(relaxed_method(4), "method");
    StageEnds ends;
    SynthesisContext ctx;
    ctx.quick = true;
    ctx.seed = 7;
    ctx.observers.push_back(&ends);
    const PointSet out = method->synthesize(ex, ctx);
    // per class: sigma 1, sigma 2, border relax
    REQUIRE(ends.labels.size() == static_cast<size_t>(3 * classes));
    size_t band_points = 0, moved = 0;
    for (int c = 0; c < classes; ++c) {
      const size_t r = 3 * c + 2;
      CHECK(ends.labels[r].find("border relax") != std::string::npos);
      check_band_relax(ends.points[r - 1], ends.points[r], c, band, band_points, moved);
    }
    CHECK(band_points > 0);
    CHECK(moved > band_points / 2);
    CHECK(same_bits(out, ends.points.back()));
  }
}

TEST_CASE("by default the relaxes follow every class's sigma stages, which stay the paper's bit for bit", "[optim][border_relax]") {
  const PointSet ex = test::small_exemplar(2, false);
  const double band = mean_nn_distance(ex) / 2;
  auto run = [&](const json& method_json, StageEnds& ends) {
    auto method = MethodRegistry::instance().create(method_json, "method");
    SynthesisContext ctx;
    ctx.quick = true;
    ctx.seed = 7;
    ctx.observers.push_back(&ends);
    return method->synthesize(ex, ctx);
  };
  json after_all = relaxed_method(4);
  after_all["border_relax"].erase("after");  // the default: "all"
  StageEnds relaxed, paper;
  const PointSet out = run(after_all, relaxed);
  run(relaxed_method(0), paper);
  REQUIRE(paper.labels.size() == 4);
  REQUIRE(relaxed.labels.size() == 6);
  CHECK(relaxed.labels[4] == "class 1/2 (id 0), border relax");
  CHECK(relaxed.labels[5] == "class 2/2 (id 1), border relax");
  for (size_t i = 0; i < 4; ++i) CHECK(same_bits(relaxed.points[i], paper.points[i]));
  // Each relax moves its class's band only: every point of the other class stays too.
  for (int c = 0; c < 2; ++c) {
    size_t band_points = 0, moved = 0;
    check_band_relax(relaxed.points[3 + c], relaxed.points[4 + c], c, band, band_points, moved);
    INFO("class " << c);
    CHECK(band_points > 0);
    CHECK(moved > band_points / 2);
  }
  CHECK(same_bits(out, relaxed.points.back()));
  // It resumes bit for bit from inside the first relax and from inside the last.
  auto whole_run = test::checkpointed_run(after_all, ex, 5, nullptr);
  const std::vector<std::string>& cps = whole_run.checkpoints;
  const PointSet& whole = whole_run.output;
  REQUIRE(cps.size() > 10);
  for (size_t i : {cps.size() - 7, cps.size() - 2}) {
    INFO("checkpoint " << i);
    CHECK(same_bits(test::checkpointed_run(after_all, ex, 5, &cps[i]).output, whole));
  }
  json bad = after_all;
  bad["border_relax"]["after"] = "each";
  OutputShape square;
  square.upscale = 2;
  CHECK(relax_options(resolve_gabor_settings(method_params(after_all), ex, square, false)).after_all);
  // One class: after it is after all, the plan "class" makes, bit for bit.
  const PointSet one = test::small_exemplar(1, false);
  auto one_run = [&](const json& m) {
    auto method = MethodRegistry::instance().create(m, "method");
    SynthesisContext ctx;
    ctx.quick = true;
    ctx.seed = 7;
    return method->synthesize(one, ctx);
  };
  CHECK(same_bits(one_run(after_all), one_run(relaxed_method(4))));
  CHECK_THROWS_WITH(resolve_gabor_settings(method_params(bad), ex, square, false), Catch::Contains("method.border_relax.after"));
}

TEST_CASE("the border relax's separation acts in the relax stages only, and keeps their pairs apart", "[optim][border_relax][isa]") {
  // Class 0 a 3 x 3 lattice: its pairs are wide (1/3), so the output's best-candidate start
  // has pairs closer than the term's threshold for it to act on; class 1 four points.
  PointSet ex;
  for (int i = 0; i < 9; ++i) ex.add({(i % 3 + 0.5) / 3, (i / 3 + 0.5) / 3}, 0);
  for (const Vec2 p : {Vec2{0.1, 0.1}, Vec2{0.6, 0.2}, Vec2{0.3, 0.7}, Vec2{0.8, 0.8}}) ex.add(p, 1);
  auto stage_ends = [&](double separation, uint64_t seed) {
    auto method = MethodRegistry::instance().create(relaxed_method(4, separation), "method");
    StageEnds ends;
    SynthesisContext ctx;
    ctx.quick = true;
    ctx.seed = seed;
    ctx.observers.push_back(&ends);
    method->synthesize(ex, ctx);
    REQUIRE(ends.points.size() == 6);  // per class: sigma 1, sigma 2, border relax
    return ends.points;
  };
  // What the term asks for: fewer of class 0's pairs inside its threshold (0.9 x the
  // exemplar's closest pair / u, on the output's torus) than the relax alone leaves.
  auto shortfall = [](const PointSet& p) {
    const PointSet c = p.subset_class(0);
    const double t = 0.9 * (1.0 / 3) / 2;
    double sum = 0;
    for (size_t i = 0; i < c.size(); ++i)
      for (size_t j = i + 1; j < c.size(); ++j) {
        const double dx = std::abs(c[i].x - c[j].x), dy = std::abs(c[i].y - c[j].y);
        sum += std::max(0.0, t - std::hypot(std::min(dx, 1 - dx), std::min(dy, 1 - dy)));
      }
    return sum;
  };
  // Decided over three seeds, each paired with itself without the term: the term's effect
  // must show in every one, not in one draw's trajectory.
  for (uint64_t seed : {7, 8, 9}) {
    INFO("seed " << seed);
    const auto off = stage_ends(0, seed), on = stage_ends(50, seed);
    // Class 0's sigma stages are the paper's, bit for bit: the term waits for the relax.
    CHECK(same_bits(off[0], on[0]));
    CHECK(same_bits(off[1], on[1]));
    CHECK_FALSE(same_bits(off[2], on[2]));
    INFO("before the relax " << shortfall(off[1]) << ", relax alone " << shortfall(off[2]) << ", with the term " << shortfall(on[2]));
    CHECK(shortfall(on[2]) < shortfall(off[2]));
  }
}

TEST_CASE("a class is relaxed when it or an earlier class parks; a run where none parks is the paper's bit for bit", "[optim][border_relax]") {
  const PointSet ex = test::small_exemplar(2, false);
  uint64_t seed = 0;
  auto run = [&](const json& method_json, StageEnds* ends, StagesReport* stages = nullptr) {
    auto method = MethodRegistry::instance().create(method_json, "method");
    SynthesisContext ctx;
    ctx.quick = true;
    ctx.seed = seed;
    ctx.stages = stages;
    if (ends) ctx.observers.push_back(ends);
    return method->synthesize(ex, ctx);
  };
  // Class 0's share within 1 % of the edge when its relax starts, over uniform points' share:
  // the first seed whose class 0 has a point there (tiny runs have few).
  StageEnds always;
  double parked = 0;
  for (seed = 1; seed <= 30 && parked == 0; ++seed) {
    always = StageEnds{};
    run(relaxed_method(4, 1.0, 0), &always);
    REQUIRE(always.points.size() == 6);
    parked = border_fraction(always.points[1].subset_class(0)) / uniform_border_fraction(Domain{});
  }
  --seed;
  INFO("seed " << seed << ": class 0 parks " << parked << " x uniform");
  REQUIRE(parked > 0);
  auto class0_moved = [](const StageEnds& e) {
    const PointSet before = e.points[1].subset_class(0), after = e.points[2].subset_class(0);
    return !same_bits(before, after);
  };
  CHECK(class0_moved(always));
  // A bound just under its share relaxes it; at its share (not above it) the class stays put.
  StageEnds under, at;
  StagesReport under_stats, at_stats;
  run(relaxed_method(4, 1.0, parked * 0.99), &under, &under_stats);
  run(relaxed_method(4, 1.0, parked), &at, &at_stats);
  CHECK(class0_moved(under));
  CHECK_FALSE(class0_moved(at));
  // The run's stages say what decided it, and that the relax ran no iteration.
  REQUIRE(at_stats.stages.size() == 6);
  CHECK(at_stats.stages[2].details["parked_over_uniform"].get<double>() == Approx(parked));
  CHECK(at_stats.stages[2].iterations == 0);
  CHECK(at_stats.stages[2].details["relaxed"] == false);
  // The relax stage's beginning says it to the progress log; a sigma stage has no note.
  REQUIRE(at.notes.size() == 6);
  CHECK(at.notes[1].empty());
  CHECK_THAT(at.notes[2], Catch::Contains("x uniform points' share within 1 % of the edge") && Catch::EndsWith("nothing to move"));
  CHECK_THAT(under.notes[2], Catch::EndsWith("relaxing its band"));
  CHECK_FALSE(at_stats.stages[1].details.contains("parked_over_uniform"));
  // Class 1 parks less than the bound in both runs; once class 0 was relaxed, it is relaxed
  // too (its pairs with class 0 across the seam were never measured before), else not.
  REQUIRE(under_stats.stages.size() == 6);
  const double class1 = under_stats.stages[5].details["parked_over_uniform"].get<double>();
  INFO("class 1 parks " << class1 << " x uniform");
  REQUIRE(class1 <= parked * 0.99);
  CHECK(under_stats.stages[2].details["relaxed"] == true);
  CHECK(under_stats.stages[5].details["relaxed"] == true);
  CHECK(!same_bits(under.points[4].subset_class(1), under.points[5].subset_class(1)));
  CHECK(at_stats.stages[5].details["relaxed"] == false);
  CHECK(same_bits(at.points[4].subset_class(1), at.points[5].subset_class(1)));
  // No class parks above a bound of 1000: the relax moves nothing and the output is the
  // published plan's (no relax stages) bit for bit.
  CHECK(same_bits(run(relaxed_method(4, 1.0, 1000), nullptr), run(relaxed_method(0), nullptr)));
  // The bound is checked where it is read.
  json bad = relaxed_method(4);
  bad["border_relax"]["parked"] = -1;
  CHECK_THROWS_WITH(method_params(bad), Catch::Contains("method.border_relax.parked"));
}

TEST_CASE("a run with a border relax resumes from any checkpoint bit for bit", "[optim][border_relax][checkpoint]") {
  const PointSet ex = test::small_exemplar(2, true);
  auto run = [&](int iterations, const std::string* resume, std::vector<std::string>* saved) {
    auto r = test::checkpointed_run(relaxed_method(iterations), ex, 5, resume);
    if (saved) *saved = std::move(r.checkpoints);
    return r.output;
  };
  std::vector<std::string> cps;
  const PointSet whole = run(4, nullptr, &cps);
  REQUIRE(cps.size() > 20);
  // Inside the first class's relax (after its 2 x 5 sigma iterations), between classes, in the last relax.
  for (size_t i : {size_t{13}, cps.size() / 2, cps.size() - 2}) {
    INFO("checkpoint " << i);
    CHECK(same_bits(run(4, &cps[i], nullptr), whole));
  }
  CHECK_FALSE(same_bits(run(0, nullptr, nullptr), whole));
}

TEST_CASE("method.border_relax is refused where there is no grid edge, naming the key", "[optim][border_relax]") {
  const PointSet ex = test::small_exemplar(1, false);
  OutputShape square;
  square.upscale = 2;
  json relax = {{"type", "gabor"}, {"border_relax", {{"iterations", 10}}}};
  CHECK(relax_options(resolve_gabor_settings(method_params(relax), ex, square, false)).iterations == 10);
  CHECK(relax_options(resolve_gabor_settings(method_params(relax), ex, square, true)).iterations == 4);  // --quick's cap
  const OutputShape rect = resolve_output_shape(resolve_run_config(json{{"output", {{"size", {2, 2}}}}}, {}), ex);
  CHECK_THROWS_WITH(resolve_gabor_settings(method_params(relax), ex, rect, false), Catch::Contains("method.border_relax"));
  json tiles = relax;
  tiles["measure"] = "tiles";
  CHECK_THROWS_WITH(resolve_gabor_settings(method_params(tiles), ex, square, false), Catch::Contains("method.border_relax"));
  json bad_lr = relax;
  bad_lr["border_relax"]["lr"] = -1;
  CHECK_THROWS_WITH(resolve_gabor_settings(method_params(bad_lr), ex, square, false), Catch::Contains("method.border_relax.lr"));
  json bad_separation = relax;
  bad_separation["border_relax"]["separation"] = -1;
  CHECK_THROWS_WITH(method_params(bad_separation), Catch::Contains("method.border_relax.separation"));
  json bad_band = relax;
  bad_band["border_relax"]["band"] = 0;
  CHECK_THROWS_WITH(method_params(bad_band), Catch::Contains("method.border_relax.band"));
  json fraction = relax;
  fraction["border_relax"]["iterations"] = 2.5;
  CHECK_THROWS_WITH(resolve_gabor_settings(method_params(fraction), ex, square, false), Catch::Contains("method.border_relax.iterations"));
  json word = relax;
  word["border_relax"]["iterations"] = "many";
  CHECK_THROWS_WITH(resolve_gabor_settings(method_params(word), ex, square, false), Catch::Contains("method.border_relax.iterations"));
  // Off (0 iterations, as configs/runs set it) it is the paper's plan, wherever the output goes.
  json off = relax;
  off["border_relax"]["iterations"] = 0;
  CHECK(relax_options(resolve_gabor_settings(method_params(off), ex, square, false)).iterations == 0);
  CHECK(relax_options(resolve_gabor_settings(method_params(off), ex, rect, false)).iterations == 0);
}

TEST_CASE("by default (null, \"auto\") the border is relaxed on the u x u square measured as one grid, and nowhere else", "[optim][border_relax]") {
  const PointSet ex = test::small_exemplar(1, false);
  OutputShape square;
  square.upscale = 2;
  const json plain = {{"type", "gabor"}};
  CHECK(method_params(plain)["border_relax"]["iterations"].is_null());
  json named = plain;
  named["border_relax"] = {{"iterations", "auto"}};
  CHECK(relax_options(resolve_gabor_settings(method_params(named), ex, square, false)).iterations == 60);
  CHECK(relax_options(resolve_gabor_settings(method_params(plain), ex, square, false)).iterations == 60);
  CHECK(relax_options(resolve_gabor_settings(method_params(plain), ex, square, true)).iterations == 4);  // --quick's cap
  // No fixed grid edge: a rectangle (output.border instead), tiles, rolled.
  const OutputShape rect = resolve_output_shape(resolve_run_config(json{{"output", {{"size", {2, 2}}}}}, {}), ex);
  CHECK(relax_options(resolve_gabor_settings(method_params(plain), ex, rect, false)).iterations == 0);
  for (const char* measure : {"tiles", "rolled"}) {
    json m = plain;
    m["measure"] = measure;
    CHECK(relax_options(resolve_gabor_settings(method_params(m), ex, square, false)).iterations == 0);
  }
  json own = plain;
  own["map_terms"] = {{"class_own", {{"weight", 1}}}};
  // Map terms leave the relax stages out (their maps are the unrolled grid's): the two combine.
  CHECK(relax_options(resolve_gabor_settings(method_params(own), test::small_exemplar(2, false), square, false)).iterations == 60);
  CHECK(relax_options(resolve_gabor_settings(method_params(own), ex, square, false)).iterations == 60);
  // The shipped paper configs keep the published border.
  for (const char* name : {"lines", "lemon_4c_v2", "poisson_n64c2_point", "ps_Tree1"}) {
    INFO(name);
    const json run = load_config(std::string(PPSYNTH_SOURCE_DIR) + "/configs/runs/" + name + ".json");
    CHECK(run["method"]["border_relax"]["iterations"] == 0);
  }
}
