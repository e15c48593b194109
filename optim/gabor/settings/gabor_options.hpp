#pragma once
// The Gabor method's own keys, typed: the sigma schedule, the neighbors, the iterations, the
// class order, where the losses measure; each declared once, here, with its default and its
// range. The method's blocks have their own (grid_options.hpp, window_options.hpp,
// quick_options.hpp; a class-end stage kind's, where the kind registers: stage_kind.hpp); its
// parts are specs that their registries resolve (rasterizer, feature_net, losses, optimizer,
// convergence, init, map_terms, terms). gabor_defaults() and gabor_bounds()
// (optim/gabor/resolution/gabor_resolution.hpp) put them all together.
#include <nlohmann/json.hpp>

#include <vector>

namespace ppsynth {

struct GaborOptions {
  double c1 = 0, c2 = 0;       // the sigma schedule's (optim/gabor/settings/sigma_schedule.hpp)
  int num_sigmas = 0;
  int k = 0;                   // neighbors per grid position: min(M, k)
  bool k_per_stage = true;     // M = the exemplar points of the stage's classes (else all)
  bool jitter = true;          // grid positions jittered every iteration
  int max_iterations = 0;      // per sigma stage
  std::vector<int> class_order;  // empty: file order (checked against the exemplar's classes later)
  bool fresh_net_per_class = false;
  // Where the losses measure the output of the paper's u x u square: its whole grid as
  // published, exemplar-sized tiles cut at a random offset, or the grid rolled by one
  // (optim/gabor/stages/random_tiles.hpp).
  enum class Measure { grid, tiles, rolled };
  Measure measure = Measure::grid;

  static nlohmann::json defaults();
  static nlohmann::json bounds();
  // From the method's params (defaults merged, bounds checked by the method's registry);
  // errors name method.<key>.
  static GaborOptions resolve(const nlohmann::json& params);
};

const char* measure_name(GaborOptions::Measure m);

}  // namespace ppsynth
