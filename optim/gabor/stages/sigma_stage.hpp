#pragma once
// The paper's stage: every moving point moves, on the maps of one sigma, until the stopping
// rule or method.max_iterations ends it (method.measure "rolled" rolls the torus itself).
#include "optim/gabor/stages/stage_kind.hpp"

namespace ppsynth {

class SigmaStage : public StageKind {
 public:
  std::string label() const override { return "sigma"; }
  int iteration_cap(const GaborSettings& settings) const override;
  bool judged() const override { return true; }
  bool rolls_grid() const override { return false; }
};

}  // namespace ppsynth
