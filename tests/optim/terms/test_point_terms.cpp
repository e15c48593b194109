// Point terms are pluggable: a term written and registered in this file (no other edit)
// is switched on by method.terms.<name> and acts in a synthesis; bad names and keys are
// refused with the key path.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/generators/lattices.hpp"
#include "optim/method/method.hpp"
#include "optim/terms/point_term.hpp"

using namespace ppsynth;

namespace {

// Pulls the moving points towards the center of the square.
class PullToCentre : public PointTerm {
 public:
  explicit PullToCentre(const nlohmann::json&) {}
  void begin_class(const ClassStage&) override { ++classes_seen; }
  torch::Tensor evaluate(const torch::Tensor& moving, const torch::Tensor&) override {
    return (moving - 0.5).pow(2).sum(-1).mean();
  }
  static inline int classes_seen = 0;
};

double mean_distance_to_center(const PointSet& ps) {
  double s = 0;
  for (size_t i = 0; i < ps.size(); ++i) s += std::hypot(ps[i].x - 0.5, ps[i].y - 0.5);
  return s / ps.size();
}

}  // namespace

PPSYNTH_REGISTER(ppsynth::PointTermRegistry, "test_pull_to_center", (nlohmann::json{{"weight", 0.0}}),
                 (nlohmann::json{{"weight", "[0, inf)"}}),
                 "test only: pulls points to the center",
                 [](const nlohmann::json& p, const std::string& key) -> std::unique_ptr<ppsynth::PointTerm> {
                   return std::make_unique<PullToCentre>(p);
                 })

TEST_CASE("A point term registered in a test file acts in a synthesis", "[optim][point_terms][synthesis]") {
  auto ex = jittered_grid_points(16, 5);
  for (size_t i = 0; i < ex.size(); i += 2) ex.set_cls(i, 1);  // two classes: two class stages
  SynthesisContext ctx;
  ctx.quick = true;
  ctx.seed = 4;
  auto run = [&](nlohmann::json terms) {
    // The paper's plan: one group of stages per class (the border relax and the revisit would
    // add more).
    nlohmann::json spec = {{"type", "gabor"}, {"terms", terms}, {"border_relax", {{"iterations", 0}}}, {"revisit", {{"iterations", 0}}}};
    return MethodRegistry::instance().create(spec, "method")->synthesize(ex, ctx);
  };
  const auto plain = run(nlohmann::json::object());
  PullToCentre::classes_seen = 0;
  const auto pulled = run({{"test_pull_to_center", {{"weight", 1000.0}}}});
  CHECK(PullToCentre::classes_seen == 2);
  INFO("plain " << mean_distance_to_center(plain) << " pulled " << mean_distance_to_center(pulled));
  CHECK(mean_distance_to_center(pulled) < mean_distance_to_center(plain) - 0.01);
  // weight 0: not created, not run.
  PullToCentre::classes_seen = 0;
  run({{"test_pull_to_center", {{"weight", 0.0}}}});
  CHECK(PullToCentre::classes_seen == 0);

  CHECK_THROWS_WITH(run({{"no_such_term", {{"weight", 1.0}}}}), Catch::Contains("method.terms.no_such_term") && Catch::Contains("separation"));
  CHECK_THROWS_WITH(run({{"test_pull_to_center", {{"weight", 1.0}, {"strength", 2}}}}), Catch::Contains("method.terms.test_pull_to_center.strength"));
  CHECK_THROWS_WITH(run({{"test_pull_to_center", {{"weight", -1.0}}}}), Catch::Contains("method.terms.test_pull_to_center.weight"));
  CHECK_THROWS_WITH(run({{"test_pull_to_center", 3}}), Catch::Contains("method.terms.test_pull_to_center"));
}
