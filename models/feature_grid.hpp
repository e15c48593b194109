#pragma once
// The evaluation grid of the feature maps (method.md section 2): `res` positions per axis at
// linspace(b, 1-b, res) with b = 1/(res+1). x runs along image columns, y along rows, as in
// the published code. The output grid is the exemplar grid times the upscaling u.
#include <cstdint>
#include <vector>

namespace ppsynth {

struct FeatureGrid {
  int res = 128;  // positions per axis
  double border() const { return 1.0 / (res + 1); }
  double coord(int i) const { return border() + (1.0 - 2.0 * border()) * i / (res - 1); }
  // Flat res*res*2 coordinates (x, y) in row-major order: index = row*res + col.
  std::vector<float> positions() const;
};

// res = clamp(round(9/d), lo, hi), d = mean nearest-neighbor distance of the exemplar.
int grid_resolution_for(double mean_nn_distance, int lo = 128, int hi = 256);

}  // namespace ppsynth
