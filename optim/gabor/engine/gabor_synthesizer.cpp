#include "optim/gabor/engine/gabor_synthesizer.hpp"

#include "optim/gabor/engine/gabor_engine.hpp"
#include "optim/gabor/resolution/gabor_resolution.hpp"

namespace ppsynth {

PointSet GaborSynthesizer::synthesize(const PointSet& exemplar, const SynthesisContext& ctx) {
  GaborEngine engine(p_, exemplar, ctx);
  return engine.run();
}

}  // namespace ppsynth

PPSYNTH_REGISTER(ppsynth::MethodRegistry, "gabor", ppsynth::gabor_defaults(),
                 ppsynth::gabor_bounds(),
                 "Huang et al. 2022: Gabor maps + random filters + Gram/correlation losses",
                 [](const ppsynth::json& p, const std::string& key) -> std::unique_ptr<ppsynth::SynthesisMethod> {
                   return std::make_unique<ppsynth::GaborSynthesizer>(p);
                 })
