#include "optim/gabor/settings/grid_options.hpp"

#include <algorithm>
#include <cmath>

#include "core/config/config.hpp"
#include "models/feature_grid.hpp"

namespace ppsynth {

namespace {
constexpr const char* k_key = "method.grid";
}  // namespace

nlohmann::json GridOptions::defaults() {
  // res 0 = clamp(round(9/d), min_res, max_res); per_sigma: coarser grids at the coarser
  // sigmas (per_stage below), the finest stage's grid unchanged
  return {{"res", 0}, {"min_res", 128}, {"max_res", 256}, {"per_sigma", false}};
}

nlohmann::json GridOptions::bounds() {
  return {{"res", "0 or int [8, 8192]"}, {"min_res", "int [8, 8192]"}, {"max_res", "int [8, 8192]"}};
}

GridOptions GridOptions::resolve(const nlohmann::json& block, double mean_nn_distance) {
  GridOptions o;
  o.res = get_int(block, "res", k_key);
  if (o.res == 0) o.res = grid_resolution_for(mean_nn_distance, get_int(block, "min_res", k_key), get_int(block, "max_res", k_key));
  o.per_sigma = get_bool(block, "per_sigma", k_key);
  return o;
}

std::vector<int> GridOptions::per_stage(const std::vector<double>& sigmas, int res) const {
  std::vector<int> r;
  for (double sigma : sigmas)
    r.push_back(per_sigma ? std::max(8, static_cast<int>(std::ceil(res * sigmas.back() / sigma - 1e-9))) : res);
  return r;
}

}  // namespace ppsynth
