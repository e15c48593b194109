#pragma once
// method.grid, typed: the exemplar grid's resolution and the coarser grids of the coarser
// sigmas, each parameter declared once, here, with its default and its range (gabor_defaults()
// and gabor_bounds() list its block from defaults() and bounds()).
#include <nlohmann/json.hpp>

#include <vector>

namespace ppsynth {

struct GridOptions {
  int res = 0;             // exemplar grid positions per exemplar unit (resolved: never 0)
  bool per_sigma = false;  // coarser grids at the coarser sigmas, the finest stage's unchanged

  static nlohmann::json defaults();
  static nlohmann::json bounds();
  // From the method's grid block (defaults merged, bounds checked by the method's registry);
  // res 0 resolves from the exemplar's mean nearest-neighbor distance d as
  // clamp(round(9 / d), min_res, max_res). Errors name method.grid.<key>.
  static GridOptions resolve(const nlohmann::json& block, double mean_nn_distance);
  // The grid of each sigma stage (coarse -> fine) for an exemplar grid of `res`: `res` at every
  // stage, or with per_sigma res * sigma_finest / sigma (at least 8): each stage's maps are
  // sampled as finely per sigma as the finest stage's (the Gabor frequencies scale with 1/sigma).
  std::vector<int> per_stage(const std::vector<double>& sigmas, int res) const;
};

}  // namespace ppsynth
