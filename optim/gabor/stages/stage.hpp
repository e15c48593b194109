#pragma once
// Stage: one step of a plan (optim/gabor/stages/stage_plan.hpp), the type alone. Its two
// policies are held by pointer, so that the geometries and the kinds, which read a stage,
// include this file and not the plan's.
#include <memory>
#include <string>
#include <vector>

namespace ppsynth {

class StageGeometry;
class StageKind;

struct Stage {
  std::string label;                   // "class 1/2 (id 0), sigma 1/4": progress and loss curves
  int group = 0;                       // stages of a group continue one optimization of `moving`
  int sigma_index = 0;                 // picks the learning rate of a per-sigma list
  double sigma = 0;
  int k = 0;                           // neighbors per grid position
  std::vector<int> target_classes;     // exemplar classes the targets are computed from
  int own_class = -1;                  // the moving class (for per-class terms); -1: none
  // Where its points live (optim/gabor/stages/stage_geometry.hpp): the unit torus, or a window.
  std::shared_ptr<const StageGeometry> geometry;
  // What the stage does with its points (optim/gabor/stages/stage_kind.hpp): the paper's sigma stage,
  // or a class-end kind (the border relax) after the finest sigma, with its settings.
  std::shared_ptr<StageKind> kind;
  std::vector<size_t> moving, frozen;  // indices into the output (the torus plan's; windows choose their own)
};

using SynthesisPlan = std::vector<Stage>;

}  // namespace ppsynth
