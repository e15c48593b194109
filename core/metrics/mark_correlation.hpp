#pragma once
// Stoyan's mark correlation function of a pattern with a numeric mark (an attribute column),
// with f(m1, m2) = m1 m2, as spatstat.explore 3.0's markcorr computes it (method "density"):
//
//   k_mm(r) = sum_{i != j} kappa(r - d_ij) m_i m_j e_ij / (E_f * sum_{i != j} kappa(r - d_ij) e_ij)
//
// over ordered pairs with d_ij <= r_max, E_f = mean(m)^2 (so k_mm = 1 for marks independent
// of position; > 1 where close points carry large marks together). kappa is a Gaussian of
// standard deviation bw = bw.nrd0 of those pairs' distances (R's rule of thumb:
// 0.9 min(sd, IQR / 1.34) n^(-1/5)); e_ij the edge weight (edge_correction.hpp). The default
// r grid is K's (second_order.hpp, lambda = n / |W|). Evaluated as the exact kernel sums
// where R's density() bins the distances first (tests/core/test_spatstat_estimators.cpp
// states the tolerance). Marks must be >= 0 with a mean > 0 (spatstat refuses the same when
// normalizing): InputError naming the attribute.
// Memory O(n + R): the pairs are found again for each sum (the bandwidth's mean, spread and
// quartiles, stream_order_statistics.hpp, then the curve) instead of being held.
#include <cstddef>
#include <functional>
#include <vector>

#include "core/metrics/edge_correction.hpp"
#include "core/point_set.hpp"

namespace ppsynth {

struct MarkCorrelation {
  std::vector<double> r, k;
  double bandwidth = 0;  // the Gaussian's standard deviation
};

MarkCorrelation mark_correlation(const PointSet& ps, size_t attribute, EdgeCorrection c, std::vector<double> r = {});

// Calls its argument once for every value, the same values each call (in the same order, so
// that sums over them are reproducible).
using ValueReplay = std::function<void(const std::function<void(double)>&)>;

// R's bw.nrd0 of the values `replay` produces (quantiles of type 7); NaN for fewer than 2.
// Three replays when they are at most 2^20, usually four beyond.
double bandwidth_nrd0(const ValueReplay& replay);

}  // namespace ppsynth
