#pragma once
// Overlap of disk patterns (points with an attribute "radius", domain units): disks i and j
// overlap when |x_i - x_j| < r_i + r_j (plane distances, or toroidal when `periodic`).
// Reported per unordered class pair (ci <= cj) and for all classes together:
//   pairs            : number of overlapping pairs
//   pair_fraction    : pairs / number of candidate pairs (n(n-1)/2 within a class,
//                      n_ci * n_cj across classes)
//   point_fraction   : fraction of the points of those classes overlapping at least one
//                      disk of the pair's other class (within a class: any other disk)
// A point set without a "radius" attribute, or with a negative or NaN radius, throws
// InputError (naming the point). Cost: O(N log N) plus the pairs within reach (each pair is
// searched from its larger disk, within twice its radius); disks larger than the points'
// bounding box (e.g. radius 1e300) overlap everything and are counted, not searched.
// More than `max_pair_classes` classes: only the first entry (all classes together) is
// returned (the K (K + 1) / 2 class pairs would not fit a table).
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

struct OverlapCount {
  int ci = -1, cj = -1;  // -1, -1 = all classes together
  size_t pairs = 0;
  double pair_fraction = 0;
  double point_fraction = 0;
};

// First entry: all classes together; then every class pair ci <= cj.
inline constexpr int kMaxPairClasses = 64;
std::vector<OverlapCount> disk_overlaps(const PointSet& ps, bool periodic = false,
                                        int max_pair_classes = kMaxPairClasses);

}  // namespace ppsynth
