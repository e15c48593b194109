#pragma once
// GaborSynthesizer: the paper's method (method "gabor"), one driver for every input kind:
// single-class, multi-class, attributes and disks are data (which points move, which are
// frozen, which weights enter the maps), not separate optimizers. It runs the paper's plan
// (optim/gabor/stages/stage_plan.hpp: per class, per sigma) on the GaborEngine (optim/gabor/engine/gabor_engine.hpp),
// which keeps its state explicit and so can checkpoint and resume. Output: u^2 copies of each
// class's exemplar count, attributes tiled (radius divided by u), every point with its class.
// Defaults: gabor_defaults() in optim/gabor/resolution/gabor_resolution.cpp (`ppsynth config --defaults`).
#include "optim/gabor/resolution/gabor_resolution.hpp"
#include "optim/method/method.hpp"

namespace ppsynth {

class GaborSynthesizer : public SynthesisMethod {
 public:
  // The params read once, when the method is created (read_gabor_params); each synthesis
  // resolves them for its exemplar and output.
  explicit GaborSynthesizer(GaborParams params) : p_(std::move(params)) {}
  PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) override;
  bool can_resume() const override { return true; }

 private:
  GaborParams p_;
};

}  // namespace ppsynth
