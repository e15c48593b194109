// Every numeric parameter of every registered part has a declared range, and every default
// lies inside it: every numeric parameter is range-checked where it is declared.
#include <catch2/catch.hpp>

#include "core/config/param_bounds.hpp"
#include "core/generators/generator.hpp"
#include "losses/loss.hpp"
#include "models/feature_net.hpp"
#include "models/rasterizer.hpp"
#include "optim/steps/initializer.hpp"
#include "optim/method/method.hpp"
#include "optim/gabor/stages/map_term.hpp"
#include "optim/gabor/stages/stage_kind.hpp"
#include "optim/terms/point_term.hpp"
#include "optim/steps/position_optimizer.hpp"
#include "optim/steps/stopping_rule.hpp"

namespace {

template <class Registry>
void check_registry(const std::string& kind) {
  const nlohmann::json all = Registry::instance().describe();
  for (auto it = all.begin(); it != all.end(); ++it) {
    INFO(kind << " '" << it.key() << "'");
    const auto& defaults = it.value()["defaults"];
    const auto& bounds = it.value()["bounds"];
    CHECK(ppsynth::unbounded_numbers(defaults, bounds).empty());
    CHECK_NOTHROW(ppsynth::check_bounds(defaults, bounds, kind));
  }
}

}  // namespace

TEST_CASE("every registered part declares the range of each numeric parameter", "[config][bounds]") {
  check_registry<ppsynth::MethodRegistry>("method");
  check_registry<ppsynth::RasterizerRegistry>("rasterizer");
  check_registry<ppsynth::FeatureNetRegistry>("feature_net");
  check_registry<ppsynth::LossRegistry>("loss");
  check_registry<ppsynth::OptimizerRegistry>("optimizer");
  check_registry<ppsynth::InitializerRegistry>("init");
  check_registry<ppsynth::PointTermRegistry>("term");
  check_registry<ppsynth::MapTermRegistry>("map_term");
  check_registry<ppsynth::StageKindRegistry>("stage_kind");
  check_registry<ppsynth::StoppingRuleRegistry>("convergence");
  check_registry<ppsynth::GeneratorRegistry>("generator");
}
