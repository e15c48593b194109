#include "models/feature_grid.hpp"

#include <algorithm>
#include <cmath>

namespace ppsynth {

std::vector<float> FeatureGrid::positions() const {
  const int R = num_rows();
  std::vector<float> p(static_cast<size_t>(R) * res * 2);
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < res; ++c) {
      p[2 * (static_cast<size_t>(r) * res + c)] = static_cast<float>(coord(c));
      p[2 * (static_cast<size_t>(r) * res + c) + 1] = static_cast<float>(coord(r));
    }
  return p;
}

int grid_rows(int cols, double aspect) {
  // The top edge lies (cols + 1) aspect spacings up; row rows - 1 lies rows spacings up. The
  // tolerance keeps a square exactly square.
  return std::max(2, static_cast<int>(std::ceil((cols + 1) * aspect - 1 - 1e-9)));
}

int grid_resolution_for(double d, int lo, int hi) {
  const double r = std::round(9.0 / d);
  return static_cast<int>(std::clamp<double>(r, lo, hi));
}

}  // namespace ppsynth
