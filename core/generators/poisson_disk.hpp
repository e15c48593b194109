#pragma once
// Dart-throwing Poisson-disk sampling: candidates are drawn uniformly and kept when no
// accepted point lies closer than `radius` (toroidal distance when `d.periodic`).
// `radius` is the minimum distance d_min between points (domain units). radius <= 0 derives
// it from a target relative radius rho (Lagae & Dutre 2008): d_min = 2 rho r_max with
// r_max = sqrt(A / (2 sqrt(3) n)) (densest-packing disk radius). Dart throwing saturates
// near rho ~ 0.75, so the default rho = 0.65 reaches n points with modest effort.
// Gives up after `max_attempts` consecutive rejections; then returns fewer than n points
// and logs a warning, or throws InputError when `require_all` is true.
// Registered as "poisson_disk" {radius, relative_radius, max_attempts, require_all}.
#include <cstdint>

#include "core/point_set.hpp"

namespace ppsynth {

template <class T>
class ParamTable;

struct PoissonDiskOptions {
  double radius = 0;            // minimum distance between points (domain units); 0 = derive
  double relative_radius = 0.65;  // used when radius <= 0
  int max_attempts = 100000;      // consecutive rejected candidates before giving up
  bool require_all = false;       // throw instead of returning fewer than n points
  static const ParamTable<PoissonDiskOptions>& params();  // its keys, defaults and ranges (the .cpp)
};

PointSet poisson_disk_points(size_t n, uint64_t seed, Domain d = {},
                             const PoissonDiskOptions& opt = {});

}  // namespace ppsynth
