#pragma once
// Random tiles: the output measured as the exemplar is (`method.measure: "tiles"`), and the
// torus rolled under the whole grid (`"rolled"`).
//
// The exemplar is one window of a pattern that goes on past its edges; its maps fall off
// near its border and its Gram and correlation targets include that fall-off. The paper
// measures the u x u output's whole grid, which has a smaller share of border, and the
// output imitates the missing fall-off by parking points on its border (docs/lab/method_measurements.md
// "Border parking"). Here the output (a torus) is cut at a random offset into u x u tiles
// the exemplar's size; each tile's points alone are rasterized on the exemplar's grid and
// measured against the exemplar's targets. Every tile then has the exemplar's geometry, so
// the targets ask it for nothing the pattern cannot give; and as the cut moves with every
// iteration, no place on the torus is a tile edge for long: nothing has a border to park on.
#include <torch/torch.h>

#include <cstdint>
#include <vector>

namespace ppsynth {

struct Tile {
  torch::Tensor rows;   // int64 indices into the points, in the tile
  torch::Tensor local;  // their positions in the tile's own unit square (differentiable)
};

// The cut's offset in [0, 1/u)^2, a function of (seed, stage, iteration) alone: a resumed run
// cuts where the uninterrupted one did without state in the checkpoint.
std::pair<double, double> tile_offset(uint64_t seed, int stage, int iteration, int u);

// `points` (N x 2, the unit torus, may require grad) rolled by `offset`: frac(p - offset),
// with an identity gradient. `method.measure: "rolled"` measures the whole grid of these,
// at tile_offset(seed, stage, iteration, 1): the grid's edge, where the paper's points park,
// lies somewhere else at every iteration.
torch::Tensor roll_torus(const torch::Tensor& points, std::pair<double, double> offset);

// `points` (N x 2, the unit torus, may require grad) cut into u x u tiles at `offset`:
// tile (i, j) holds the points p with frac(p - offset) in [i/u, (i+1)/u) x [j/u, (j+1)/u),
// at u * frac(p - offset) - (i, j). Tiles without points are left out.
std::vector<Tile> cut_into_tiles(const torch::Tensor& points, int u, std::pair<double, double> offset);

}  // namespace ppsynth
