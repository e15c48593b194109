#pragma once
// A synthesis is a plan: stages run in order over one output pattern. A stage says which
// output points move and which stay frozen, the scale (sigma) and neighbor count (k) of its
// maps, and which exemplar classes its targets come from. Stages of one group share the
// moving points' optimization (the paper: the sigmas of one class continue from each other's
// unwrapped positions); a new group starts from the output's wrapped positions.
//
// The paper's plan (class_sigma_plan): one group per class in class order, one stage per
// sigma, earlier classes frozen, the maps on the unit square read as a torus; with
// method.border_relax one more stage per class relaxes its border band: after every class's
// stages, a group of its own each (border_relax.after "all", the default), or last in its
// class's group ("class"). The windows of
// a large canvas (optim/gabor/window_plan.hpp) are another plan for the same engine
// (optim/gabor/gabor_engine.hpp): the same class and sigma stages, once per window.
#include <string>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

struct GaborSettings;

// Where a stage's maps are computed, in output coordinates. The grid covers the square
// `grid`; positions enter the maps in its local coordinates, (p - corner) / side.
struct StageWindow {
  Domain grid{};           // a square
  bool torus = true;       // the paper: moving positions wrap on the unit square
  // Windows (torus false) choose their points when their group starts, from the positions
  // of the moment: the moving ones are the class's points inside `movable` not yet final;
  // frozen are the other points of the stage's classes inside `context` (the grid and the
  // reach of the maps beyond it). Moving points stay inside `movable`; the ones inside
  // `interior` when the group ends are final (no later window moves them).
  Domain movable{}, interior{}, context{};
  int index = 0, count = 1;  // window i of n (0-based)
};

// A grid-local position (u, v) in output coordinates: on the torus as it is; in a window,
// corner + side * (u, v) kept inside `movable`. Local positions are float: a point held at the
// movable edge in float maps back up to a few 1e-8 beyond it, and an output point outside
// its domain is one the readers refuse.
Vec2 to_output(const StageWindow& window, double u, double v);

struct Stage {
  std::string label;                   // "class 1/2 (id 0), sigma 1/4": progress and loss curves
  int group = 0;                       // stages of a group continue one optimization of `moving`
  int sigma_index = 0;                 // picks the learning rate of a per-sigma list
  double sigma = 0;
  int k = 0;                           // neighbors per grid position
  std::vector<int> target_classes;     // exemplar classes the targets are computed from
  int own_class = -1;                  // the moving class (for per-class terms); -1: none
  StageWindow window;
  // method.border_relax: only the moving points near the grid's edge move (those within the
  // band when the stage starts), on the grid rolled every iteration, for a fixed number of
  // iterations (no stopping rule).
  bool border_relax = false;
  std::vector<size_t> moving, frozen;  // indices into the output (torus plans; windows choose their own)
};

using SynthesisPlan = std::vector<Stage>;

// `out_index[c]`: the output indices of class c.
SynthesisPlan class_sigma_plan(const PointSet& exemplar, const GaborSettings& settings,
                               const std::vector<std::vector<size_t>>& out_index);

}  // namespace ppsynth
