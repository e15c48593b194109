#pragma once
// Mitchell's best-candidate sampling: each new point is the best of m * (current count)
// uniform candidates (at least 1), "best" = farthest from its nearest accepted point,
// measured toroidally over the full domain so the pattern tiles. The candidates are drawn in
// the sub-window shrunk by `margin` on every side (as a fraction of width/height); the
// published code initializes with n points in [0.01, 0.99]^2, i.e. margin = 0.01 (the
// default). margin = 0 gives the classic toroidal best-candidate pattern.
// The candidates are handed out to cells and drawn only in the cells that could hold the best
// one (candidate_cells.hpp): the pattern has the distribution of Mitchell's, drawn with other
// random numbers than drawing all m * count candidates (O(m n^2)), in a small part of its time.
// Registered as "best_candidate" {m, margin}.
#include <cstdint>
#include <functional>

#include "core/point_set.hpp"

namespace ppsynth {

template <class T>
class ParamTable;

struct BestCandidateOptions {
  double m = 10;        // candidates per accepted point
  double margin = 0.01;  // candidates drawn in [x0+margin*W, x1-margin*W] x (same in y)
  // Called every thousand points when set (a caller's stop check, which may throw).
  std::function<void()> poll;
  static const ParamTable<BestCandidateOptions>& params();  // its keys, defaults and ranges (the .cpp)
};

PointSet best_candidate_points(size_t n, uint64_t seed, Domain d = {},
                               const BestCandidateOptions& opt = {});

}  // namespace ppsynth
