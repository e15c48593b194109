#pragma once
// The "gabor" method's parameters, typed: its own keys (the sigma schedule, the neighbors, the
// iterations, the class order, where the losses measure), its blocks (grid_options.hpp,
// window_options.hpp, quick_options.hpp) and its parts' specs, which their registries resolve
// (rasterizer, feature_net, losses, optimizer, convergence, init, map_terms, terms); each key
// declared once in its table (gabor_options.cpp), its default the member's initializer below.
// A class-end stage kind's block (method.<name>) is the kind's own (stage_kind.hpp);
// gabor_defaults() and gabor_bounds() (optim/gabor/resolution/gabor_resolution.hpp) add them.
#include <vector>

#include <nlohmann/json.hpp>

#include "core/config/params.hpp"
#include "optim/gabor/settings/grid_options.hpp"
#include "optim/gabor/settings/quick_options.hpp"
#include "optim/gabor/settings/window_options.hpp"

namespace ppsynth {

// The maps' own default neighbor count (GaborMapsOptions::k, models/gabor_feature_maps.hpp),
// taken from there rather than copied (that header is torch's).
int gabor_maps_default_k();

struct GaborOptions {
  // The sigma schedule's (optim/gabor/settings/sigma_schedule.hpp): sigma from d / c1 to d / c2.
  double c1 = 1.0, c2 = 2.6;
  int num_sigmas = 4;
  int k = gabor_maps_default_k();  // neighbors per grid position: min(M, k)
  bool k_per_stage = true;       // M = the exemplar points of the stage's classes (else all)
  bool jitter = true;            // grid positions jittered every iteration
  int max_iterations = 500;      // per sigma stage
  std::vector<int> class_order;  // empty: file order (checked against the exemplar's classes later)
  bool fresh_net_per_class = false;
  // Where the losses measure the output of the paper's u x u square: its whole grid as
  // published, exemplar-sized tiles cut at a random offset, or the grid rolled by one
  // (optim/gabor/stages/random_tiles.hpp).
  enum class Measure { grid, tiles, rolled };
  Measure measure = Measure::grid;
  nlohmann::json map_attributes;  // null or "auto": every non-constant attribute; or a list of names
  GridOptions grid;
  WindowOptions window;  // rectangle outputs run window by window
  QuickOptions quick;    // --quick: every knob that sets the cost, shrunk
  // The parts, as specs their registries resolve.
  nlohmann::json rasterizer = {{"type", "gabor"}};
  nlohmann::json feature_net = {{"type", "random"}};
  nlohmann::json losses = nlohmann::json::array({nlohmann::json{{"type", "gram"}, {"layers", {0, 1, 2}}, {"weight", 0.08}},
                                                 nlohmann::json{{"type", "correlation"}, {"layers", {2}}, {"weight", 1.0}}});
  nlohmann::json optimizer = {{"type", "adam"}};
  nlohmann::json convergence = {{"type", "loss"}};
  nlohmann::json init = {{"type", "best_candidate"}};
  // A term whose registered weight is > 0 is on without being named here (class_own:
  // optim/terms/weighted_terms.hpp); configs/methods/gabor_published.json sets it to 0.
  nlohmann::json map_terms = nlohmann::json::object();
  nlohmann::json terms = nlohmann::json::object();

  static const ParamTable<GaborOptions>& params();
};

const char* measure_name(GaborOptions::Measure m);

}  // namespace ppsynth
