// Map terms are pluggable: a term written and registered in this file (no other edit) is
// switched on by method.map_terms.<name>, is told of the run, every group and every stage,
// gets the evaluation's jitter, and acts in a synthesis; bad names and keys are refused with
// the key path. (The built-in "class_own" term: tests/optim/gabor/test_synthesis.cpp.)
#include <catch2/catch.hpp>

#include <cmath>

#include "core/generators/lattices.hpp"
#include "optim/gabor/stages/map_term.hpp"
#include "optim/gabor/stages/stage_kind.hpp"
#include "optim/method/method.hpp"

using namespace ppsynth;

namespace {

// Pulls the moving points towards the center, and counts what the engine told it.
class CenterMapTerm : public MapTerm {
 public:
  explicit CenterMapTerm(const nlohmann::json&) {}
  void begin_run(const MapTermRun& run) override { ++runs, grid = run.settings.res; }
  void begin_group(const MapTermGroup& g) override { ++groups, output_points = g.output.size(); }
  void begin_stage(const Stage& s) override { ++stages, rolled_stages += s.kind->rolls_grid(); }
  torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& jitter, const Stage& s) override {
    ++evaluations, rolled_evaluations += s.kind->rolls_grid();
    if (jitter.defined()) ++with_jitter;
    return (moving - 0.5).pow(2).sum(-1).mean();
  }
  static void reset() { runs = groups = stages = rolled_stages = evaluations = rolled_evaluations = with_jitter = grid = 0, output_points = 0; }
  static inline int runs = 0, groups = 0, stages = 0, rolled_stages = 0, evaluations = 0, rolled_evaluations = 0, with_jitter = 0, grid = 0;
  static inline size_t output_points = 0;
};

double mean_distance_to_center(const PointSet& ps) {
  double s = 0;
  for (size_t i = 0; i < ps.size(); ++i) s += std::hypot(ps[i].x - 0.5, ps[i].y - 0.5);
  return s / ps.size();
}

}  // namespace

PPSYNTH_REGISTER(ppsynth::MapTermRegistry, "test_center", (nlohmann::json{{"weight", 0.0}}),
                 (nlohmann::json{{"weight", "[0, inf)"}}), "test only: pulls points to the center",
                 [](const nlohmann::json& p, const std::string& key) -> std::unique_ptr<ppsynth::MapTerm> {
                   return std::make_unique<CenterMapTerm>(p);
                 })

TEST_CASE("A map term registered in a test file acts in a synthesis", "[optim][map_terms][synthesis]") {
  auto ex = jittered_grid_points(16, 5);
  for (size_t i = 0; i < ex.size(); i += 2) ex.set_cls(i, 1);  // two classes: two groups of stages
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 4;
  auto run = [&](nlohmann::json terms, nlohmann::json relax = {{"iterations", 0}}) {
    nlohmann::json spec = {{"type", "gabor"}, {"map_terms", terms}, {"border_relax", relax}, {"revisit", {{"iterations", 0}}}};
    return MethodRegistry::instance().create(spec, "method")->synthesize(ex, ctx);
  };
  const auto plain = run(nlohmann::json::object());
  CenterMapTerm::reset();
  const auto pulled = run({{"test_center", {{"weight", 1000.0}}}});
  CHECK(CenterMapTerm::runs == 1);
  CHECK(CenterMapTerm::groups == 2);
  CHECK(CenterMapTerm::stages == 4);  // 2 classes x 2 quick sigmas
  CHECK(CenterMapTerm::evaluations >= 4);
  CHECK(CenterMapTerm::with_jitter == CenterMapTerm::evaluations);  // jitter is on by default
  CHECK(CenterMapTerm::grid == 24);                                  // the --quick grid
  CHECK(CenterMapTerm::output_points == 64);
  INFO("plain " << mean_distance_to_center(plain) << " pulled " << mean_distance_to_center(pulled));
  CHECK(mean_distance_to_center(pulled) < mean_distance_to_center(plain) - 0.01);
  // The border relax rolls the grid under the points; a map term's maps are the unrolled
  // grid's, so its stages run without the term (and the two combine).
  CenterMapTerm::reset();
  run({{"test_center", {{"weight", 1000.0}}}}, {{"iterations", 2}, {"parked", 0}, {"after", "class"}});
  CHECK(CenterMapTerm::rolled_stages == 2);  // one relax stage per class
  CHECK(CenterMapTerm::stages == 6);
  CHECK(CenterMapTerm::rolled_evaluations == 0);
  CHECK(CenterMapTerm::evaluations > 0);
  CenterMapTerm::reset();
  run({{"test_center", {{"weight", 0.0}}}});  // weight 0: not created, not run
  CHECK(CenterMapTerm::runs == 0);

  CHECK_THROWS_WITH(run({{"no_such_term", {{"weight", 1.0}}}}), Catch::Contains("method.map_terms.no_such_term") && Catch::Contains("class_own"));
  CHECK_THROWS_WITH(run({{"test_center", {{"weight", 1.0}, {"strength", 2}}}}), Catch::Contains("method.map_terms.test_center.strength"));
  CHECK_THROWS_WITH(run({{"test_center", {{"weight", -1.0}}}}), Catch::Contains("method.map_terms.test_center.weight"));
}
