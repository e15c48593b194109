#include "models/feature_net.hpp"

#include "core/config/defaults_catalog.hpp"

namespace ppsynth {

void freeze(torch::nn::Module& m) {
  for (auto& p : m.parameters()) p.set_requires_grad(false);
}

}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("feature_net", ppsynth::FeatureNetRegistry)
