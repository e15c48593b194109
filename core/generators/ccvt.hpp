#pragma once
// Capacity-constrained Voronoi tessellation (Balzer, Schloemer & Deussen 2009), discrete
// version on the torus: `points_per_site` * n sample points (a jittered grid: stratified, so
// the sampled density has little noise) are distributed among n
// sites so every site owns exactly the same number of samples (its capacity). Each
// iteration (1) swaps pairs of samples between two sites whenever that lowers the total
// squared (toroidal) distance: for sites i, j, sample a of i and b of j, swap when
// |a-i|^2 + |b-j|^2 > |a-j|^2 + |b-i|^2 (the paper's heap-based pair search, restricted to
// each site's `neighbor_sites` nearest sites, found with NeighborIndex; pairs of sites that
// did not change in the previous iteration are skipped), (2) moves each site to the
// (toroidal) centroid of its samples. Initial assignment: samples in random order go to the
// nearest site with room. Stops when an iteration makes no swap or after `max_iterations`.
// Fewer samples per site leave the discrete solution noisier, a lower relative radius, and
// more cost more time (how much: docs/lab/performance/README.md, "Numbers that were in code
// comments"; paper Table 1: 0.7341 for its CCVT exemplar).
// Cost per iteration O(n * neighbor_sites * points_per_site); 100-200 iterations typical.
// Registered as "ccvt" {points_per_site, max_iterations, neighbor_sites}.
#include <cstdint>

#include "core/point_set.hpp"

namespace ppsynth {

template <class T>
class ParamTable;

struct CcvtOptions {
  int points_per_site = 1024;  // capacity of each site
  int max_iterations = 300;
  int neighbor_sites = 6;      // swap partners considered per site (nearest sites)
  static const ParamTable<CcvtOptions>& params();  // its keys, defaults and ranges (the .cpp)
};

PointSet ccvt_points(size_t n, uint64_t seed, Domain d = {}, const CcvtOptions& opt = {});

}  // namespace ppsynth
