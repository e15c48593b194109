#include "optim/gabor/settings/grid_options.hpp"

#include <algorithm>
#include <cmath>

#include "models/feature_grid.hpp"

namespace ppsynth {

const ParamTable<GridOptions>& GridOptions::params() {
  using G = GridOptions;
  static const ParamTable<G> t("method.grid", {
      param("res", &G::res, "0 or int [8, 8192]", "exemplar grid positions per exemplar unit; 0: clamp(round(9 / d), min_res, max_res)"),
      param("min_res", &G::min_res, "int [8, 8192]", "res 0's least"),
      param("max_res", &G::max_res, "int [8, 8192]", "res 0's most"),
      param("per_sigma", &G::per_sigma, "", "coarser grids at the coarser sigmas (as fine per sigma as the finest stage's)"),
  });
  return t;
}

int GridOptions::resolved_res(double mean_nn_distance) const {
  return res != 0 ? res : grid_resolution_for(mean_nn_distance, min_res, max_res);
}

std::vector<int> GridOptions::per_stage(const std::vector<double>& sigmas, int res) const {
  std::vector<int> r;
  for (double sigma : sigmas)
    r.push_back(per_sigma ? std::max(8, static_cast<int>(std::ceil(res * sigmas.back() / sigma - 1e-9))) : res);
  return r;
}

}  // namespace ppsynth
