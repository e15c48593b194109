#pragma once
// The PPTBF point process (supplement step [3], genPointSet): a tiling of the plane into
// axis-aligned rectangular cells, an optional random subdivision of cells, and one feature
// point per (sub)cell placed at p = center + jitter * 0.9 * U[-1,1]^2 * half-size (jitter 0
// = cell centers, 1 = uniform over 90% of the cell). Optional relaxation pushes each point
// away from its three nearest neighbors (5 steps of 0.05) while keeping it in its cell.
//
// tile_type (nu_T), numbered as in the authors' public GPU implementation (the supplement
// only gives the range); "+sub" = cells split with probability 0.5 (4-way for squarish
// cells, 2-way along the long axis otherwise), "all sub" = probability 1:
//   0 regular square grid        1 regular +sub          2 regular, all sub + relaxation
//   3 regular +sub + relaxation  4 brick (rows shifted 1/2)  5 rows shifted 1/3
//   6 irregular (random row heights, random column cuts per row)   7 irregular +sub
//   8 irregular-x (random column cuts per row, equal rows)         9 irregular-x +sub
//  10 herringbone of 2:1 bricks (1/4 model unit)  11 +sub
//  12 herringbone of 3:1 bricks (1/6 model unit)  13 +sub
//  14 bisquare (Pythagorean tiling of 0.4 and 0.2 squares)          15 +sub
//  16 a-pavement (periodic 4x4 layout of 1x1,2x1,1x2,2x2 blocks, 1/4 unit) 17 +sub
// The rectangle layouts of 10..17 and the random cut ranges are our own, following the
// structure of the GPU code; the per-cell numbers come from pptbf_random.hpp (seeded).
//
// A PointProcess caches relaxed cells: it is NOT thread-safe, use one per thread.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth::pptbf_impl {

struct Rect {
  Vec2 lo, hi;
  Vec2 center() const { return {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2}; }
  Vec2 size() const { return {hi.x - lo.x, hi.y - lo.y}; }
  bool contains(Vec2 p) const { return p.x >= lo.x && p.x < hi.x && p.y >= lo.y && p.y < hi.y; }
  bool intersects(const Rect& o) const {
    return lo.x < o.hi.x && o.lo.x < hi.x && lo.y < o.hi.y && o.lo.y < hi.y;
  }
};

// Identity of a cell: tiling lattice indices (i, j), rectangle of the periodic layout (part),
// subdivision index (sub, 0 when not subdivided).
struct CellKey {
  std::int64_t i = 0, j = 0;
  int part = 0, sub = 0;
  bool operator==(const CellKey& o) const { return i == o.i && j == o.j && part == o.part && sub == o.sub; }
  std::uint64_t hash() const;
};

// The supplement's p[k], c[k] (cell lower-left corner), d[k] (cell size) and the cell id.
struct FeaturePoint {
  Vec2 p;
  Vec2 c, d;
  CellKey key;
  Vec2 cell_center() const { return {c.x + d.x / 2, c.y + d.y / 2}; }
};

struct BaseCell {
  Rect rect;
  CellKey key;
};

enum class Pavement { Grid, Herringbone, Pythagorean, APavement };

struct TilingSpec {
  Pavement pavement = Pavement::Grid;
  int row_shift_div = 1;       // grid rows shifted by (j mod div)/div
  double randx = 0, randy = 0; // grid cut randomness (cuts move by up to +-rand/2)
  int herringbone_len = 2;
  double subdiv_prob = 0;
  int relax_iters = 0;
  const char* name = "";
};

constexpr int kNumTileTypes = 18;
TilingSpec tiling_spec(int tile_type);  // InputError outside 0..17

class PointProcess {
 public:
  PointProcess(int tile_type, double jitter, std::uint64_t seed);

  const TilingSpec& spec() const { return spec_; }
  int tile_type() const { return tile_type_; }
  // The supplement's empirical window footprint: 1.5, times 0.4 for tile types >= 10.
  double footprint() const { return tile_type_ >= 10 ? 0.6 : 1.5; }
  // Half-width of the neighborhood searched by pptbf(): footprint + 1 model units.
  double reach() const { return footprint() + 1.0; }

  // Base (unsubdivided) cells whose rectangle intersects `box`.
  void base_cells_in_box(const Rect& box, std::vector<BaseCell>& out) const;
  // Feature points of every cell whose base rectangle intersects `box` (appended).
  void points_in_box(const Rect& box, std::vector<FeaturePoint>& out);
  // points_in_box of the square x +- reach.
  void points_near(Vec2 x, double reach, std::vector<FeaturePoint>& out);
  // Points of one base cell (subdivision, jitter, relaxation), deterministic.
  std::vector<FeaturePoint> points_of(const BaseCell& cell);

 private:
  std::vector<FeaturePoint> unrelaxed_points_of(const BaseCell& cell) const;
  void grid_cells(const Rect& box, std::vector<BaseCell>& out) const;
  void periodic_cells(const Rect& box, std::vector<BaseCell>& out) const;

  int tile_type_;
  TilingSpec spec_;
  double jitter_;
  std::uint64_t seed_;
  // periodic layouts: lattice vectors and rectangles of one period, in model units
  Vec2 lat_a_, lat_b_;
  std::vector<Rect> layout_;
  struct KeyHash {
    size_t operator()(const CellKey& k) const { return static_cast<size_t>(k.hash()); }
  };
  std::unordered_map<CellKey, std::vector<FeaturePoint>, KeyHash> relaxed_cache_;
};

}  // namespace ppsynth::pptbf_impl
