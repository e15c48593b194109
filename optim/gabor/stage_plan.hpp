#pragma once
// A synthesis is a plan: stages run in order over one output pattern. A stage says which
// output points move and which stay frozen, the scale (sigma) and neighbor count (k) of its
// maps, and which exemplar classes its targets come from. Stages of one group share the
// moving points' optimization (the paper: the sigmas of one class continue from each other's
// unwrapped positions); a new group starts from the output's wrapped positions.
//
// Each stage carries two policies the engine (optim/gabor/gabor_engine.hpp) asks, never
// branching on which they are: its kind (what it does with its points: the paper's sigma
// stage, the border relax; optim/gabor/stage_kind.hpp) and its geometry (where its points live:
// the unit torus, a window; optim/gabor/stage_geometry.hpp).
//
// The paper's plan (class_sigma_plan): one group per class in class order, one sigma stage per
// sigma, earlier classes frozen, on the torus; each class-end kind the settings ask for
// (method.border_relax) adds one more stage per class, at the finest sigma's settings: after
// every class's stages, a group of its own each (border_relax.after "all", the default), or
// last in its class's group ("class"). The windows of a large canvas
// (optim/gabor/window_plan.hpp) are another plan: the same class and sigma stages, once per
// window, each window's stages on its window geometry.
#include <memory>
#include <string>
#include <vector>

#include "core/point_set.hpp"
#include "optim/gabor/stage_geometry.hpp"
#include "optim/gabor/stage_kind.hpp"

namespace ppsynth {

struct GaborSettings;

struct Stage {
  std::string label;                   // "class 1/2 (id 0), sigma 1/4": progress and loss curves
  int group = 0;                       // stages of a group continue one optimization of `moving`
  int sigma_index = 0;                 // picks the learning rate of a per-sigma list
  double sigma = 0;
  int k = 0;                           // neighbors per grid position
  std::vector<int> target_classes;     // exemplar classes the targets are computed from
  int own_class = -1;                  // the moving class (for per-class terms); -1: none
  // Where its points live (optim/gabor/stage_geometry.hpp): the unit torus, or a window.
  std::shared_ptr<const StageGeometry> geometry;
  // What the stage does with its points (optim/gabor/stage_kind.hpp): the paper's sigma stage,
  // or a class-end kind (the border relax) after the finest sigma, with its settings.
  std::shared_ptr<StageKind> kind;
  std::vector<size_t> moving, frozen;  // indices into the output (the torus plan's; windows choose their own)
};

using SynthesisPlan = std::vector<Stage>;

// `out_index[c]`: the output indices of class c.
SynthesisPlan class_sigma_plan(const PointSet& exemplar, const GaborSettings& settings,
                               const std::vector<std::vector<size_t>>& out_index);

}  // namespace ppsynth
