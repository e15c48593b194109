#pragma once
// GaborSynthesizer: the paper's method (method "gabor"), one driver for every input kind.
//
//   for each class stage (class order; earlier classes frozen, maps from classes 0..k):
//     for each sigma (coarse -> fine, sigma_schedule):
//       exemplar -> Rasterizer -> FeatureNet -> loss targets          (once per sigma)
//       repeat: wrap(moving) + frozen -> Rasterizer(u) -> FeatureNet -> CompositeLoss
//               [+ class_own_weight x the same on the moving class alone, classes after the
//                first; not in the paper, off by default]
//               [+ point terms on the positions (method.terms: separation, pcf_match,
//                ...; optim/point_term.hpp); not in the paper, none by default]
//               -> backward -> PositionOptimizer step                 (until ConvergenceRule)
//
// Single-class, multi-class, attributes and disks are data here (which points move, which are
// frozen, which weights enter the maps), not separate optimisers. Output: u^2 copies of each
// class's exemplar count, attributes tiled (radius divided by u), every point with its class.
// Defaults: gabor_defaults() in optim/gabor_pipeline.cpp (`ppsynth config --defaults`).
#include "optim/gabor_pipeline.hpp"
#include "optim/method.hpp"

namespace ppsynth {

class GaborSynthesizer : public SynthesisMethod {
 public:
  explicit GaborSynthesizer(json params) : p_(std::move(params)) {}
  PointSet synthesize(const PointSet& exemplar, const SynthesisContext& ctx) override;

 private:
  json p_;
};

}  // namespace ppsynth
