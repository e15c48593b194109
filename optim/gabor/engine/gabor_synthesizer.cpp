#include "optim/gabor/engine/gabor_synthesizer.hpp"

#include "optim/gabor/engine/gabor_engine.hpp"

namespace ppsynth {

PointSet GaborSynthesizer::synthesize(const PointSet& exemplar, const SynthesisContext& ctx) {
  GaborEngine engine(p_, exemplar, ctx);
  return engine.run();
}

}  // namespace ppsynth

// Not PPSYNTH_REGISTER_PARAMS: the method's params are its table's keys (GaborOptions) and the
// block of each stage kind, declared in the kind's own table wherever it registers (in either
// order), so its defaults and bounds are put together by gabor_defaults() and gabor_bounds(),
// and its factory reads both (read_gabor_params), refusing a key that nothing reads.
PPSYNTH_REGISTER(ppsynth::MethodRegistry, "gabor", ppsynth::gabor_defaults(),
                 ppsynth::gabor_bounds(),
                 "Huang et al. 2022: Gabor maps + random filters + Gram/correlation losses",
                 [](const ppsynth::json& p, const std::string& key) -> std::unique_ptr<ppsynth::SynthesisMethod> {
                   return std::make_unique<ppsynth::GaborSynthesizer>(ppsynth::read_gabor_params(p, key));
                 })
