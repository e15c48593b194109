#pragma once
// Lloyd relaxation on the torus: start from uniform points, then `iterations` times move each
// site to the (toroidal) centroid of its Voronoi cell. Cells are approximated by a dense
// sample set: `samples_per_point` * n uniform samples (fresh each iteration, seeded), each
// assigned to its nearest site via NeighborIndex (periodic). Centroids are computed as a
// circular mean relative to the site so cells crossing the border are handled.
// Registered as "lloyd" {iterations, samples_per_point}.
#include <cstdint>

#include "core/point_set.hpp"

namespace ppsynth {

template <class T>
class ParamTable;

struct LloydOptions {
  int iterations = 10;
  int samples_per_point = 64;
  static const ParamTable<LloydOptions>& params();  // its keys, defaults and ranges (the .cpp)
};

PointSet lloyd_points(size_t n, uint64_t seed, Domain d = {}, const LloydOptions& opt = {});

// One Lloyd step in place (exposed for reuse by other relaxations); returns the mean site
// displacement.
double lloyd_step(PointSet& ps, size_t samples, uint64_t seed);

}  // namespace ppsynth
