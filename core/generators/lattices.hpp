#pragma once
// Grid-based processes.
// - jittered_grid: the domain is cut into a c x r grid of cells (c*r >= n, c/r close to the
//   domain's aspect ratio, c = ceil(sqrt(n*W/H))); n cells (all when c*r == n, else a seeded
//   random subset) each get one point uniform within the cell scaled by `jitter` (1 = full
//   cell, 0 = cell center). Registered as "jittered_grid" {jitter}.
// - regular_grid: the same cells' centers, no randomness except which cells are used when
//   c*r > n. Registered as "regular_grid".
// - hexagonal_lattice: a perfect triangular (hexagonal-packing) lattice with `cols` points a
//   row and an even number of rows, rows offset by half a spacing; the row spacing is chosen
//   so the lattice tiles the torus: spacing a = W/cols, rows = round(H / (a*sqrt(3)/2))
//   rounded to even. It is exactly equilateral when H/W = rows*sqrt(3)/(2*cols); on the unit
//   square, n = cols*rows points is only close to the requested n (cols = round(sqrt(
//   n sqrt(3) / 2)), rows even; e.g. n = 256 gives 15 x 18 = 270). A global random offset (seeded) is applied when `random_offset`.
//   Registered as "hexagonal_lattice" {random_offset}.
//   hexagonal_domain(cols, rows) returns the rectangle [0,1] x [0, rows*sqrt(3)/(2*cols)]
//   on which the lattice is perfect (relative radius 1 when taken as a torus of that area).
#include <cstdint>

#include "core/point_set.hpp"

namespace ppsynth {

PointSet jittered_grid_points(size_t n, uint64_t seed, Domain d = {}, double jitter = 1.0);
PointSet regular_grid_points(size_t n, uint64_t seed, Domain d = {});
PointSet hexagonal_lattice_points(size_t n, uint64_t seed, Domain d = {},
                                  bool random_offset = false);
// Exactly cols x rows lattice points (rows must be even) in `d`.
PointSet hexagonal_lattice_exact(size_t cols, size_t rows, Domain d);
Domain hexagonal_domain(size_t cols, size_t rows);

}  // namespace ppsynth
