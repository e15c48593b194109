// Every part of every registry reads exactly the keys its defaults declare: built from its
// defaults it reads no key they lack (a read of an undeclared key is a logic_error), built
// without any one of them it fails (every declared key is read), and a key beside them that
// nothing reads is refused. And each declared key has its doc line for the reference.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include <torch/torch.h>

#include "core/config/param_docs.hpp"
#include "core/generators/generator.hpp"
#include "core/output_shape.hpp"
#include "losses/loss.hpp"
#include "models/feature_net.hpp"
#include "models/rasterizer.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/gabor/stages/map_term.hpp"
#include "optim/gabor/stages/stage_kind.hpp"
#include "optim/method/method.hpp"
#include "optim/steps/initializer.hpp"
#include "optim/steps/position_optimizer.hpp"
#include "optim/steps/stopping_rule.hpp"
#include "optim/run/run_config.hpp"
#include "optim/terms/point_term.hpp"
#include "tests/support/gabor_runs.hpp"
#include "tests/support/small_exemplar.hpp"

using namespace ppsynth;

namespace {

// `build(name, params)` builds the part `name` of registry R from `params` as its factory would
// get them (defaults merged, "type" gone). Parts that test files register to show the JSON form
// (a Python part's) are named test_* and left out.
template <class R, class Build>
void check_reads(const std::string& kind, Build build) {
  const auto& registry = R::instance();
  int parts = 0;
  for (const std::string& name : registry.names()) {
    if (name.rfind("test_", 0) == 0) continue;
    ++parts;
    INFO(kind << " '" << name << "'");
    const json defaults = registry.entry(name).defaults;
    CHECK_NOTHROW(build(name, defaults));
    for (auto it = defaults.begin(); it != defaults.end(); ++it) {
      INFO("without its declared key '" << it.key() << "'");
      json less = defaults;
      less.erase(it.key());
      CHECK_THROWS_AS(build(name, less), std::logic_error);
    }
    json more = defaults;
    more["zz_declared_by_no_one"] = 1;
    CHECK_THROWS_WITH(build(name, more), Catch::Matchers::Contains("zz_declared_by_no_one"));
  }
  CHECK(parts > 0);
}

// The registry's own factory, with the arguments the run gives it.
template <class R, class... Args>
auto by_factory(const std::string& kind, Args... args) {
  return [kind, args...](const std::string& name, const json& params) {
    R::instance().entry(name).make(params, kind, args...);
  };
}

}  // namespace

TEST_CASE("every registered part reads each key its defaults declare, and no other", "[config][params]") {
  const PointSet ex = test::small_exemplar(2, false);
  const OutputShape square;
  const GaborSettings settings = resolve_gabor_settings(test::method_params(json{{"type", "gabor"}}), ex, square, false);

  check_reads<MethodRegistry>("method", by_factory<MethodRegistry>("method"));
  check_reads<StageKindRegistry>("method.stage", by_factory<StageKindRegistry>("method.stage", std::cref(settings)));
  RasterizerArgs raster;
  raster.k = 4;  // the method's, which a Gabor raster needs
  check_reads<RasterizerRegistry>("method.rasterizer", by_factory<RasterizerRegistry>("method.rasterizer", raster));
  check_reads<FeatureNetRegistry>("method.feature_net", by_factory<FeatureNetRegistry>("method.feature_net", 1, uint64_t{1}));
  check_reads<LossRegistry>("method.losses", by_factory<LossRegistry>("method.losses"));
  const torch::Tensor positions = torch::zeros({4, 2}, torch::requires_grad());
  check_reads<OptimizerRegistry>("method.optimizer", by_factory<OptimizerRegistry>("method.optimizer", positions, 0));
  check_reads<InitializerRegistry>("method.init", by_factory<InitializerRegistry>("method.init"));
  check_reads<StoppingRuleRegistry>("method.convergence", by_factory<StoppingRuleRegistry>("method.convergence"));
  check_reads<PointTermRegistry>("method.terms", by_factory<PointTermRegistry>("method.terms"));
  check_reads<MapTermRegistry>("method.map_terms", by_factory<MapTermRegistry>("method.map_terms"));
  check_reads<GeneratorRegistry>("generator", by_factory<GeneratorRegistry>("generator"));
}

namespace {

// The keys of `defaults` (dotted; a part's spec, a list or an empty object is one key) that
// `docs` gives no line. Parts and blocks that test files register (test_*) are left out.
void undocumented(const json& defaults, const json& docs, const std::string& prefix, std::vector<std::string>& out) {
  for (auto it = defaults.begin(); it != defaults.end(); ++it) {
    const std::string key = prefix + it.key();
    if (key.rfind("test_", 0) == 0) continue;  // a test file's stage kind's block under the gabor method
    const json* d = docs.is_object() && docs.contains(it.key()) ? &docs[it.key()] : nullptr;
    if (it->is_object() && !it->empty() && !it->contains("type") && d && d->is_object())
      undocumented(*it, *d, key + ".", out);
    else if (!d || !d->is_string() || d->get<std::string>().empty())
      out.push_back(key);
  }
}

template <class R>
void check_docs(const std::string& kind) {
  const auto& registry = R::instance();
  for (const std::string& name : registry.names()) {
    if (name.rfind("test_", 0) == 0) continue;
    INFO(kind << " '" << name << "'");
    std::vector<std::string> missing;
    undocumented(registry.entry(name).defaults, param_docs(kind, name), "", missing);
    CHECK(missing == std::vector<std::string>{});
  }
}

}  // namespace

TEST_CASE("every registered part's declared keys have their doc lines for the reference", "[config][params][docs]") {
  check_docs<MethodRegistry>("method");  // the gabor method's stage kinds' blocks among its own
  check_docs<RasterizerRegistry>("rasterizer");
  check_docs<FeatureNetRegistry>("feature_net");
  check_docs<LossRegistry>("loss");
  check_docs<OptimizerRegistry>("optimizer");
  check_docs<InitializerRegistry>("initializer");
  check_docs<StoppingRuleRegistry>("convergence");
  check_docs<PointTermRegistry>("point_term");
  check_docs<MapTermRegistry>("map_term");
  check_docs<GeneratorRegistry>("generator");
  // The run config's own keys, its output and runtime blocks included.
  std::vector<std::string> missing;
  undocumented(run_defaults(), param_docs("run", "run"), "", missing);
  CHECK(missing == std::vector<std::string>{});
}

