#pragma once
// The field's second-order summaries of a point pattern on a rectangle, with spatstat's
// conventions (spatstat.explore 3.0: Kest, Lest, pcf.ppp, Kcross, pcfcross), so that a number
// printed here can be put beside R's:
//
//   K(r) = |W| / (n (n - 1)) * sum_{i != j} 1{d_ij <= r} e_ij            Ripley's K
//   L(r) = sqrt(K(r) / pi)                                                (Poisson: L(r) = r)
//   g(r) = |W| / (n (n - 1)) * sum_{i != j} kappa_h(r - d_ij) e_ij / (2 pi r)   pair correlation
//
// over ordered pairs, with e_ij the edge weight of the pair (edge_correction.hpp: translation
// or isotropic, centered on i). Cross-type (points of type a to points of type b, a != b; the
// two sets share one window): n (n - 1) becomes n_a n_b and the sums run over a x b.
//   kappa_h  Epanechnikov kernel of half-width h, 3/(4h) (1 - t^2/h^2) on |t| < h: spatstat's
//            default (kernel "epanechnikov", bw = h / sqrt(5)) with h = 0.15 / sqrt(lambda)
//            (Stoyan's rule, stoyan = 0.15), lambda the intensity of the second set (the only
//            set for univariate g; the j points for cross-type, as pcfcross).
//   r        spatstat's default grid: 513 evenly spaced values from 0 to r_max, with
//            r_max = min(shorter side / 4, sqrt(1000 / (pi lambda))) (rmax.rule "K"),
//            lambda as for h; or any grid given.
// g is evaluated as the exact kernel sum, where spatstat's density() bins the distances onto
// 1024 points first: the two differ by the binning error, a few 1e-3 relative (tests/core
// test_spatstat_estimators.cpp states the tolerance it checks). g(0) is NaN (1/r).
// Fewer than 2 points (univariate) or an empty set (cross-type) give NaN curves.
// Cost: a k-d tree radius search per point of a plus O(1) per pair within r_max (K) and
// O(h / r step) per pair within r_max + h (g). Memory: O(n + R); the pairs (about 1000 per
// point at spatstat's r_max) are summed as they are found, never held.
#include <cstddef>
#include <vector>

#include "core/metrics/edge_correction.hpp"
#include "core/neighbors.hpp"
#include "core/point_set.hpp"

namespace ppsynth {

// Number of values of spatstat's default r grid.
inline constexpr size_t kSpatstatRValues = 513;
// Stoyan's rule for the pair correlation's kernel: h = kStoyan / sqrt(lambda).
inline constexpr double kStoyan = 0.15;

// rmax.rule("K", W, lambda).
double spatstat_r_max(const Domain& window, double lambda);
// 0, step, ..., r_max as spatstat's make.even.breaks lays it (513 values).
std::vector<double> spatstat_r_grid(const Domain& window, double lambda);

// Calls f(i, j, d) for every ordered pair (i of a, j of b) with d <= reach; b == nullptr: the
// pairs of a with i != j. In increasing i, each i's pairs by increasing distance (the same
// order every call, so sums over it are reproducible). One point's neighbors are held at a
// time; a caller's stop check (core/poll.hpp) runs at every point's search.
template <class F>
void for_each_close_pair(const PointSet& a, const PointSet* b, double reach, F&& f) {
  const PointSet& to = b ? *b : a;
  if (a.empty() || to.empty()) return;
  const NeighborIndex index(to.positions());
  std::vector<double> dist;
  for (size_t i = 0; i < a.size(); ++i) {
    const std::vector<size_t> near = index.radius(a[i], reach, &dist);
    for (size_t k = 0; k < near.size(); ++k)
      if (b || near[k] != i) f(i, near[k], dist[k]);
  }
}

struct SecondOrder {
  std::vector<double> r, k, l, g;
  double bandwidth = 0;  // the kernel's half-width h
};

// K, L and g of a (b == nullptr) or of a to b (cross-type) on a's window, under `c`.
// `r` empty: spatstat's default grid. `with_g` false leaves g empty (the verdict's K-only use).
SecondOrder second_order(const PointSet& a, const PointSet* b, EdgeCorrection c, std::vector<double> r = {},
                         bool with_g = true);

}  // namespace ppsynth
