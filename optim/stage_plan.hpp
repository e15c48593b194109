#pragma once
// A synthesis is a plan: stages run in order over one output pattern. A stage says which
// output points move and which stay frozen, the scale (sigma) and neighbour count (k) of its
// maps, and which exemplar classes its targets come from. Stages of one group share the
// moving points' optimisation (the paper: the sigmas of one class continue from each other's
// unwrapped positions); a new group starts from the output's wrapped positions.
//
// The paper's plan (class_sigma_plan): one group per class in class order, one stage per
// sigma, earlier classes frozen. Another kind of plan (windows of a large canvas, say) is a
// different function producing stages for the same engine (optim/gabor_engine.hpp).
#include <string>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

struct GaborSettings;

struct Stage {
  std::string label;                   // "class 1/2 (id 0), sigma 1/4": progress and loss curves
  int group = 0;                       // stages of a group continue one optimisation of `moving`
  int sigma_index = 0;                 // picks the learning rate of a per-sigma list
  double sigma = 0;
  int k = 0;                           // neighbours per grid position
  std::vector<int> target_classes;     // exemplar classes the targets are computed from
  int own_class = -1;                  // the moving class (for per-class terms); -1: none
  std::vector<size_t> moving, frozen;  // indices into the output
};

using SynthesisPlan = std::vector<Stage>;

// `out_index[c]`: the output indices of class c.
SynthesisPlan class_sigma_plan(const PointSet& exemplar, const GaborSettings& settings,
                               const std::vector<std::vector<size_t>>& out_index);

}  // namespace ppsynth
