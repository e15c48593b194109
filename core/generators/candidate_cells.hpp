#pragma once
// CandidateCells: Mitchell's best-candidate step (best_candidate.hpp) without drawing every
// candidate. The best of K uniform candidates is the candidate farthest from the accepted
// points; the domain is cut into cells, each knowing the largest nearest-point distance of any
// spot in it (exact: max_nearest_distance below). A step hands its K candidates out to the
// cells in decreasing order of that largest distance, as a multinomial drawn cell by cell (the
// count in a cell is binomial among the candidates left, with the cell's share of the window's
// area left), draws each cell's candidates uniformly in it, and stops at the first cell whose
// largest distance cannot beat the best candidate so far: the candidates of the cells after it
// would all lose. The best candidate therefore has the distribution of the best of K uniform
// candidates, while a step draws only those of the cells near the largest holes.
// The cells hold a quarter of the area per point of the count the pattern will have at the
// next doubling (rebuilt at each doubling), so that a cell sees a few points and an accepted
// point changes a few cells. A step visits the cells whose largest distance beats its winner:
// their number grows with the count, far slower than the m * count candidates Mitchell's
// method draws (docs/lab/performance/README.md, "Best-candidate initialization", says how much).
// Internal helper of the generators.
#include <cstdint>
#include <random>
#include <vector>

#include "core/generators/dynamic_grid.hpp"
#include "core/point_set.hpp"

namespace ppsynth::gen_detail {

// max over q in `rect` of min over `sites` of |q - s| (sites as offsets in the same frame;
// infinity when there are none). Exact: the maximum lies at a corner, where an edge of the
// sites' Voronoi diagram crosses the rectangle's boundary, or at a Voronoi vertex inside.
double max_nearest_distance(const Domain& rect, const std::vector<Vec2>& sites);

class CandidateCells {
 public:
  // `d` the domain of the (toroidal) distances, `window` where candidates are drawn (inside
  // d), `n` the number of points the pattern will hold.
  CandidateCells(const Domain& d, const Domain& window, size_t n);

  // The best of `candidates` (>= 1) uniform candidates in the window: the farthest from the
  // accepted points (at least one).
  Vec2 best_of(size_t candidates, std::mt19937_64& rng) const;
  void accept(Vec2 p);

 private:
  void rebuild(size_t target);
  Domain rect(size_t cell) const;  // the cell's part of the window
  // The distance from q to the nearest point, searched within `guess` first (then doubled).
  double exact_nearest(Vec2 q, double guess) const;
  void measure(size_t cell);       // the cell's largest nearest-point distance
  void sift_down(size_t t);

  Domain d_, window_;
  size_t n_ = 0, target_ = 0;  // the pattern's final count; the count the cells are cut for
  double window_area_ = 0;
  DynamicGrid points_;
  size_t nx_ = 1, ny_ = 1;
  double cw_ = 0, ch_ = 0;
  std::vector<double> largest_;  // per cell: its largest nearest-point distance
  std::vector<double> area_;     // per cell: its area inside the window
  std::vector<uint32_t> heap_;   // the cells meeting the window, a max-heap on largest_
  std::vector<int64_t> slot_;    // per cell: its index in heap_, -1 when not there
};

}  // namespace ppsynth::gen_detail
