#pragma once
// The evaluation grid of the feature maps (method.md section 2): `res` positions per axis at
// linspace(b, 1-b, res) with b = 1/(res+1). x runs along image columns, y along rows, as in
// the published code. The output grid is the exemplar grid times the upscaling u.
//
// A rectangle grid (a rectangle output's, optim/gabor/windows/window_plan.hpp) has `rows` rows at the
// columns' spacing: its width is the unit, so positions and maps stay isotropic (one sigma,
// one frequency along both axes) and y runs past 1 when rows > res. rows = 0 (or res) is the
// square, position for position.
#include <cstdint>
#include <vector>

namespace ppsynth {

struct FeatureGrid {
  int res = 128;  // positions per axis (columns)
  int rows = 0;   // positions along y; 0: res (the square)
  int num_rows() const { return rows > 0 ? rows : res; }
  double border() const { return 1.0 / (res + 1); }
  // Column i's x, or row i's y (the same spacing).
  double coord(int i) const { return border() + (1.0 - 2.0 * border()) * i / (res - 1); }
  // Flat num_rows*res*2 coordinates (x, y) in row-major order: index = row*res + col.
  std::vector<float> positions() const;
};

// The rows of a grid of `cols` columns over a rectangle `aspect` (height / width) times as
// tall as wide: the fewest at the columns' spacing (row i at (i + 1) / (cols + 1) widths)
// whose last lies within one spacing of the top edge, as a square's last row does; at
// least 2. A square (aspect 1) gets cols.
int grid_rows(int cols, double aspect);

// res = clamp(round(9/d), lo, hi), d = mean nearest-neighbor distance of the exemplar.
int grid_resolution_for(double mean_nn_distance, int lo = 128, int hi = 256);

}  // namespace ppsynth
