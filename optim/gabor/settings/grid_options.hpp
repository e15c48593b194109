#pragma once
// method.grid, typed: the exemplar grid's resolution and the coarser grids of the coarser
// sigmas, each key declared once in its table (grid_options.cpp).
#include <vector>

#include "core/config/params.hpp"

namespace ppsynth {

struct GridOptions {
  int res = 0;             // exemplar grid positions per exemplar unit; 0: from the exemplar (resolved_res)
  int min_res = 128, max_res = 256;  // res 0's clamp
  bool per_sigma = false;  // coarser grids at the coarser sigmas, the finest stage's unchanged

  static const ParamTable<GridOptions>& params();
  // res, or for res 0, from the exemplar's mean nearest-neighbor distance d:
  // clamp(round(9 / d), min_res, max_res).
  int resolved_res(double mean_nn_distance) const;
  // The grid of each sigma stage (coarse -> fine) for an exemplar grid of `res`: `res` at every
  // stage, or with per_sigma res * sigma_finest / sigma (at least 8): each stage's maps are
  // sampled as finely per sigma as the finest stage's (the Gabor frequencies scale with 1/sigma).
  std::vector<int> per_stage(const std::vector<double>& sigmas, int res) const;
};

}  // namespace ppsynth
