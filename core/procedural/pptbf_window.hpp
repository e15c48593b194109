#pragma once
// PPTBF window function W (supplement step [5]) and the cell geometry it needs.
//
// Cell distance (nthclosest, and the cells themselves): for a feature point p in the cell
// rectangle [c, c+d],
//     dist(x, p) = (1 - larp) * ||x - p||_norm + larp * max(ex, ey),
// where ex = |x.x - p.x| / (distance from p.x to the rectangle side facing x), same for y:
// larp = 0 gives the Voronoi cells of the points, larp = 1 cells shaped like the tiles.
// ||.||_n is the Minkowski distance (n >= 50 is treated as L-infinity).
//
// Cellular window w1 (only in the closest cell, k = 0): cv = 1 - |x - p| / r(angle), where
// r is the distance from p to the cell border along the ray through x, taken from
//   cellborder: the exact border (bisection on "closest point is still p"; closed form
//               for the Euclidean Voronoi case larp = 0, norm = 2),
//   polygon:    the nv-gon whose vertices are border points at angles start + m 2pi/nv,
//   beziercell: that nv-gon with each corner replaced by the quadratic Bezier curve
//               (edge midpoint, vertex, next edge midpoint).
// wsmooth (lc) in [0,2] blends cv: 0 exact, 1 polygon, 2 Bezier (linear in between).
//   w1 = normblend * (exp((cv - 1) sigw1) - exp(-sigw1)), clamped at 0   (supplement)
//   w2 = (1 - normblend) * (exp(-sigw2 ||x - p||_norm) - exp(-sigw2 footprint)), clamped at 0
#include <vector>

#include "core/procedural/pptbf_tiling.hpp"

namespace ppsynth::pptbf_impl {

double minkowski(Vec2 v, double n);
double cell_distance(Vec2 x, const FeaturePoint& fp, double norm, double larp);
// Indices of `pts` sorted by cell_distance to x (the supplement's nthclosest / mink[]).
void nth_closest(Vec2 x, const std::vector<FeaturePoint>& pts, double norm, double larp,
                 std::vector<int>& order);

// Geometry of one cell, computed once per feature point (independent of the pixel).
struct CellShape {
  FeaturePoint site;
  std::vector<FeaturePoint> competitors;  // the 16 points nearest to the site
  double norm = 2, larp = 0;
  double start_angle = 0, step = 0;       // polygon vertex angles start + m * step
  std::vector<double> vertex_r;           // border distance at each vertex angle
};

// `neighbors` = feature points around the site (the site itself is skipped by key).
CellShape make_cell_shape(const FeaturePoint& site, const std::vector<FeaturePoint>& neighbors,
                          double norm, double larp, int arity, double start_angle);
// Distance from the site to its cell border along the unit direction (ux, uy).
double cellborder(const CellShape& cs, double ux, double uy);
double polygon_radius(const CellShape& cs, double angle);
double beziercell(const CellShape& cs, double angle);
// cv in [0,1] of x for smoothing lc = wsmooth (1 at the site, 0 on/after the border).
double cellular_value(const CellShape& cs, Vec2 x, double wsmooth);

double window_w1(double cv, double normblend, double sigw1);
double window_w2(double sddno, double normblend, double sigw2, double footprint);

}  // namespace ppsynth::pptbf_impl
