#include "models/feature_grid.hpp"

#include <algorithm>
#include <cmath>

namespace ppsynth {

std::vector<float> FeatureGrid::positions() const {
  std::vector<float> p(static_cast<size_t>(res) * res * 2);
  for (int r = 0; r < res; ++r)
    for (int c = 0; c < res; ++c) {
      p[2 * (static_cast<size_t>(r) * res + c)] = static_cast<float>(coord(c));
      p[2 * (static_cast<size_t>(r) * res + c) + 1] = static_cast<float>(coord(r));
    }
  return p;
}

int grid_resolution_for(double d, int lo, int hi) {
  const double r = std::round(9.0 / d);
  return static_cast<int>(std::clamp<double>(r, lo, hi));
}

}  // namespace ppsynth
