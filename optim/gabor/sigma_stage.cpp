#include "optim/gabor/sigma_stage.hpp"

#include "optim/gabor/gabor_pipeline.hpp"

namespace ppsynth {

int SigmaStage::iteration_cap(const GaborSettings& settings) const { return settings.max_iterations; }

}  // namespace ppsynth
