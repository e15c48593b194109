#include "optim/gabor/stages/sigma_stage.hpp"

#include "optim/gabor/settings/gabor_settings.hpp"

namespace ppsynth {

int SigmaStage::iteration_cap(const GaborSettings& settings) const { return settings.max_iterations; }

}  // namespace ppsynth
