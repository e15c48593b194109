#pragma once
// A synthesis is a plan: stages run in order over one output pattern. A stage says which
// output points move and which stay frozen, the scale (sigma) and neighbor count (k) of its
// maps, and which exemplar classes its targets come from. Stages of one group share the
// moving points' optimization (the paper: the sigmas of one class continue from each other's
// unwrapped positions); a new group starts from the output's wrapped positions.
//
// Each stage carries two policies the engine (optim/gabor/engine/gabor_engine.hpp) asks, never
// branching on which they are: its kind (what it does with its points: the paper's sigma
// stage, the border relax; optim/gabor/stages/stage_kind.hpp) and its geometry (where its points live:
// the unit torus, a window; optim/gabor/stages/stage_geometry.hpp).
//
// The paper's plan (class_sigma_plan): one group per class in class order, one sigma stage per
// sigma, earlier classes frozen, on the torus; each class-end kind the settings ask for
// (method.border_relax) adds one more stage per class, at the finest sigma's settings: after
// every class's stages, a group of its own each (border_relax.after "all", the default), or
// last in its class's group ("class"). The windows of a large canvas
// (optim/gabor/windows/window_plan.hpp) are another plan: the same class and sigma stages, once per
// window, each window's stages on its window geometry.
#include <memory>
#include <string>
#include <vector>

#include "core/point_set.hpp"
#include "optim/gabor/stages/stage.hpp"
#include "optim/gabor/stages/stage_geometry.hpp"
#include "optim/gabor/stages/stage_kind.hpp"

namespace ppsynth {

struct GaborSettings;

// `out_index[c]`: the output indices of class c.
SynthesisPlan class_sigma_plan(const PointSet& exemplar, const GaborSettings& settings,
                               const std::vector<std::vector<size_t>>& out_index);

}  // namespace ppsynth
