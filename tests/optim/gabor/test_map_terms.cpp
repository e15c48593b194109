// Map terms are pluggable: a term written and registered in this file (no other edit) is
// switched on by method.map_terms.<name>, is told of the run, every group and every stage,
// gets the evaluation's jitter, and acts in a synthesis; bad names and keys are refused with
// the key path. (The built-in "class_own" term: tests/optim/gabor/test_synthesis.cpp.)
#include <catch2/catch.hpp>

#include <cmath>

#include "core/generators/lattices.hpp"
#include "optim/gabor/map_term.hpp"
#include "optim/method/method.hpp"

using namespace ppsynth;

namespace {

// Pulls the moving points towards the centre, and counts what the engine told it.
class CentreMapTerm : public MapTerm {
 public:
  explicit CentreMapTerm(const nlohmann::json&) {}
  void begin_run(const MapTermRun& run) override { ++runs, grid = run.settings.res; }
  void begin_group(const Stage&, const PointSet& output) override { ++groups, output_points = output.size(); }
  void begin_stage(const Stage&) override { ++stages; }
  torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor& jitter, const Stage&) override {
    ++evaluations;
    if (jitter.defined()) ++with_jitter;
    return (moving - 0.5).pow(2).sum(-1).mean();
  }
  static void reset() { runs = groups = stages = evaluations = with_jitter = grid = 0, output_points = 0; }
  static inline int runs = 0, groups = 0, stages = 0, evaluations = 0, with_jitter = 0, grid = 0;
  static inline size_t output_points = 0;
};

double mean_distance_to_centre(const PointSet& ps) {
  double s = 0;
  for (size_t i = 0; i < ps.size(); ++i) s += std::hypot(ps[i].x - 0.5, ps[i].y - 0.5);
  return s / ps.size();
}

}  // namespace

PPSYNTH_REGISTER(ppsynth::MapTermRegistry, "test_centre", (nlohmann::json{{"weight", 0.0}}),
                 (nlohmann::json{{"weight", "[0, inf)"}}), "test only: pulls points to the centre",
                 [](const nlohmann::json& p) -> std::unique_ptr<ppsynth::MapTerm> {
                   return std::make_unique<CentreMapTerm>(p);
                 })

TEST_CASE("A map term registered in a test file acts in a synthesis", "[optim][map_terms][synthesis]") {
  auto ex = jittered_grid_points(16, 5);
  for (size_t i = 0; i < ex.size(); i += 2) ex.set_cls(i, 1);  // two classes: two groups of stages
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 4;
  auto run = [&](nlohmann::json terms) {
    nlohmann::json spec = {{"type", "gabor"}, {"map_terms", terms}};
    return MethodRegistry::instance().create(spec, "method")->synthesize(ex, ctx);
  };
  const auto plain = run(nlohmann::json::object());
  CentreMapTerm::reset();
  const auto pulled = run({{"test_centre", {{"weight", 1000.0}}}});
  CHECK(CentreMapTerm::runs == 1);
  CHECK(CentreMapTerm::groups == 2);
  CHECK(CentreMapTerm::stages == 4);  // 2 classes x 2 quick sigmas
  CHECK(CentreMapTerm::evaluations >= 4);
  CHECK(CentreMapTerm::with_jitter == CentreMapTerm::evaluations);  // jitter is on by default
  CHECK(CentreMapTerm::grid == 24);                                  // the --quick grid
  CHECK(CentreMapTerm::output_points == 64);
  INFO("plain " << mean_distance_to_centre(plain) << " pulled " << mean_distance_to_centre(pulled));
  CHECK(mean_distance_to_centre(pulled) < mean_distance_to_centre(plain) - 0.01);
  CentreMapTerm::reset();
  run({{"test_centre", {{"weight", 0.0}}}});  // weight 0: not created, not run
  CHECK(CentreMapTerm::runs == 0);

  CHECK_THROWS_WITH(run({{"no_such_term", {{"weight", 1.0}}}}), Catch::Contains("method.map_terms.no_such_term") && Catch::Contains("class_own"));
  CHECK_THROWS_WITH(run({{"test_centre", {{"weight", 1.0}, {"strength", 2}}}}), Catch::Contains("method.map_terms.test_centre.strength"));
  CHECK_THROWS_WITH(run({{"test_centre", {{"weight", -1.0}}}}), Catch::Contains("method.map_terms.test_centre.weight"));
}
