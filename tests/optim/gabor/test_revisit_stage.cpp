// method.revisit (optim/gabor/stages/revisit/revisit_stage.hpp): after every class's sigma
// stages, one stage per class where that class moves again beside all the others. On by
// default, off in the published parent (the paper's plan); a one-class plan holds no revisit.
#include <catch2/catch.hpp>

#include "core/output_shape.hpp"
#include "optim/gabor/stages/revisit/revisit_stage.hpp"
#include "optim/method/method.hpp"
#include "optim/run/run_config.hpp"
#include "tests/support/gabor_runs.hpp"
#include "tests/support/same_bits.hpp"
#include "tests/support/small_exemplar.hpp"

using namespace ppsynth;

namespace {

json revisit_method(const json& revisit) {
  return {{"type", "gabor"},
          {"border_relax", {{"iterations", 0}}},
          {"revisit", revisit},
          {"quick", {{"res", 16}, {"channels", 4}, {"max_iterations", 3}, {"num_sigmas", 2}}}};
}

// The positions of class `k` in `ps`, in order.
std::vector<Vec2> class_points(const PointSet& ps, int k) {
  std::vector<Vec2> v;
  for (size_t i = 0; i < ps.size(); ++i)
    if (ps.cls(i) == k) v.push_back(ps[i]);
  return v;
}

bool same_positions(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].x != b[i].x || a[i].y != b[i].y) return false;
  return true;
}

// A rectangle of 3 x 1.5 exemplar units at 16 positions a unit, on windows of `pixels`
// positions (24: 2 x 1 windows and more; 96: one grid), margins 0.3.
test::CheckpointedRun rectangle_run(const PointSet& ex, int pixels, const json& revisit) {
  json spec = revisit_method(revisit);
  spec["window"] = {{"pixels", pixels}, {"margin", 0.3}};
  const OutputShape shape = resolve_output_shape(resolve_run_config(json{{"output", {{"size", {3, 1.5}}}}}, {}), ex);
  return test::checkpointed_run(spec, ex, 3, nullptr, nullptr, &shape);
}

}  // namespace

TEST_CASE("revisit: after every class's sigma stages, each class moves again beside the others", "[optim][stage_kinds][revisit]") {
  const PointSet ex = test::small_exemplar(2, false);
  const auto off = test::checkpointed_run(revisit_method({{"iterations", 0}}), ex, 7);
  const auto on = test::checkpointed_run(revisit_method({{"iterations", 3}}), ex, 7);
  // Off (the published parent's): the paper's plan, 2 classes x 2 sigmas.
  REQUIRE(off.report.stages.size() == 4);
  // On: the same four stages, then one revisit per class, in the class order.
  REQUIRE(on.report.stages.size() == 6);
  for (size_t i = 0; i < 4; ++i) CHECK(on.report.stages[i].stage == off.report.stages[i].stage);
  CHECK(on.report.stages[4].stage == "class 1/2 (id 0), revisit");
  CHECK(on.report.stages[5].stage == "class 2/2 (id 1), revisit");
  for (size_t i = 4; i < 6; ++i) {
    CHECK(on.report.stages[i].iterations >= 1);
    CHECK(on.report.stages[i].iterations <= 3);
  }
  // The revisit moves class 0 after class 1 was placed: class 0 is no longer where its own
  // stages left it (the run without revisit ends there).
  CHECK_FALSE(same_positions(class_points(on.output, 0), class_points(off.output, 0)));
}

TEST_CASE("revisit stages follow every class's border relax", "[optim][stage_kinds][revisit]") {
  const PointSet ex = test::small_exemplar(2, false);
  json method = revisit_method({{"iterations", 2}});
  method["border_relax"] = {{"iterations", 2}, {"parked", 0}};
  const auto run = test::checkpointed_run(method, ex, 7);
  REQUIRE(run.report.stages.size() == 8);
  CHECK(run.report.stages[4].stage == "class 1/2 (id 0), border relax");
  CHECK(run.report.stages[5].stage == "class 2/2 (id 1), border relax");
  CHECK(run.report.stages[6].stage == "class 1/2 (id 0), revisit");
  CHECK(run.report.stages[7].stage == "class 2/2 (id 1), revisit");
}

TEST_CASE("revisit plans nothing on a one-class exemplar: its run is as without it", "[optim][stage_kinds][revisit]") {
  const PointSet ex = test::small_exemplar(1, false);
  const auto off = test::checkpointed_run(revisit_method({{"iterations", 0}}), ex, 7);
  const auto on = test::checkpointed_run(revisit_method({{"iterations", 3}}), ex, 7);
  REQUIRE(on.report.stages.size() == off.report.stages.size());
  for (size_t i = 0; i < on.report.stages.size(); ++i) CHECK(on.report.stages[i].stage == off.report.stages[i].stage);
  CHECK(test::same_bits(on.output, off.output));
  CHECK(on.checkpoints.size() == off.checkpoints.size());
}

TEST_CASE("revisit's options are checked where it declares them", "[optim][stage_kinds][revisit]") {
  CHECK(MethodRegistry::instance().entry("gabor").defaults["revisit"] == RevisitOptions::params().defaults());
  CHECK(RevisitOptions::params().defaults()["iterations"] == 100);  // on: each class moves again (docs/lab/later_classes)
  CHECK_THROWS_WITH(test::method_params(revisit_method({{"iterations", -1}})), Catch::Contains("method.revisit.iterations"));
  CHECK_THROWS_WITH(test::method_params(revisit_method({{"lr", 0}})), Catch::Contains("method.revisit.lr"));
  CHECK_THROWS_WITH(test::method_params(revisit_method({{"rounds", 2}})), Catch::Contains("method.revisit.rounds"));
}

// A class's points inside a window's interior used to be final once its own stages ended, so
// a rectangle's revisit found nothing to move and ran no iteration. They are final when the
// window's last stage ends: the revisit moves them, on one grid and window by window.
TEST_CASE("revisit moves every class again on a rectangle, on one grid and window by window", "[optim][windows][revisit]") {
  const PointSet ex = test::small_exemplar(2, false);
  for (const int pixels : {96, 24}) {
    CAPTURE(pixels);
    const auto off = rectangle_run(ex, pixels, {{"iterations", 0}});
    const auto on = rectangle_run(ex, pixels, {{"iterations", 3}});
    int revisits = 0, windows = 0;
    for (const auto& st : on.report.stages) {
      if (st.stage.find("sigma 1/2") != std::string::npos && st.stage.find("class 1/2") != std::string::npos) ++windows;
      if (st.stage.find("revisit") == std::string::npos) continue;
      CAPTURE(st.stage);
      CHECK(st.iterations >= 1);
      ++revisits;
    }
    CHECK(revisits == 2 * windows);  // one per class in every window
    CHECK((pixels == 96 ? windows == 1 : windows > 1));
    // The revisit moved points (the stages before it are the same: only it can differ; the
    // count too, as the crop to the rectangle keeps what the moves left inside).
    CHECK_FALSE(test::same_bits(on.output, off.output));
  }
}
