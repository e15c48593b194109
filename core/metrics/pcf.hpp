#pragma once
// Pair correlation function (PCF), Gaussian-kernel estimator of the thesis (Roveri,
// Chapter 4, Eq. 4.1; Oztireli & Gross 2012), over the whole domain:
//
//   g(r) = 1 / (lambda^2 * 2 pi r) * sum_{i != j} k(r - |h_ij|) / a(h_ij)
//   k(t) = exp(-t^2 / sigma^2) / (sqrt(pi) sigma)          (1-D normalized Gaussian)
//
// with h_ij = x_j - x_i, lambda^2 = N (N-1) / A^2 (unbiased for the auto-PCF; the cross-PCF
// of classes a, b uses lambda_a lambda_b = N_a N_b / A^2 and sums over i in a, j in b), and
// a(h) the translation edge correction: a(h) = (W - |h_x|)(H - |h_y|) in a rectangle,
// a(h) = A (= W H) on a torus (h then the minimum-image vector; no edge effect).
// g is dimensionless (1 = uncorrelated, 0 = no pairs at that distance).
// Near r = 0 the 1/r factor amplifies kernel mass leaking from pairs at |h| ~ sigma, so the
// first few radii can be large even for patterns with no close pairs (e.g. g(0.01) ~ 2.5 for
// a 64-point jittered grid); this is the estimator as specified, and it matches the
// reference numbers, so it is kept.
//
// Radii: everything is in units of the thesis's r_max, "the minimum distance between pairs
// of points for the maximum packing" (Lagae & Dutre 2008), i.e. the hexagonal-packing
// DISTANCE d_max = 2 * packing_radius(N, A) = sqrt(2 A / (sqrt(3) N)) (pcf_unit below), not
// the disk radius that relative_radius divides by. Checked against the reference numbers in
// shared/data/reference/README.md: with this unit the quadrant PCF MSE of `lines` comes out
// 0.0155 (reference 0.0156) and 0.146 for its initialization (0.149); with the disk radius as
// unit it would be 0.041 and 0.58.
// `bins` radii evenly spaced from r_min_factor*r_max to r_max_factor*r_max (thesis: 100
// samples up to 2.5 r_max), kernel width sigma = sigma_factor * r_max (thesis: 0.25).
// Curve::r holds the radii in r_max units (so curves of different sets line up).
// r_max: options.r_max > 0 fixes it (domain units); 0 derives it from the set's own count
// (auto-PCF: N; cross-PCF: N_a + N_b). To compare two sets (exemplar vs quadrant patch) use
// the same r_max for both: quadrant.hpp fixes it from the exemplar's count.
// Pairs farther than r_max_factor*r_max + 4 sigma are skipped (kernel < 1e-7 of its peak).
// Empty or single-point sets give g = 0 everywhere.
// Cost: a k-d tree radius search per point (O(N log N)) plus O(B) per pair closer than the
// cutoff, B ~ 0.8 bins (~44 pairs per point for a pattern of the exemplar's density: about
// O(N * 44 * B) in all; a cluster of m points within the cutoff adds m^2 pairs).
#include <cstddef>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

// Largest number of radii a curve may have (options beyond it are an InputError).
inline constexpr int kMaxBins = 100000;

struct PcfOptions {
  int bins = 100;
  double r_max_factor = 2.5;   // last radius, in r_max units
  double sigma_factor = 0.25;  // kernel width, in r_max units
  bool periodic = false;       // torus (no edge correction) instead of rectangle
  double r_max = 0;            // r_max in domain units; 0 = derive from the point count
  double r_min_factor = 0.01;  // first radius, in r_max units (avoids r = 0)
};

struct Curve {
  std::vector<double> r, g;
};

Curve pcf(const PointSet& ps, const PcfOptions& opt = {});
// Cross-PCF from the points of `a` to those of `b` (same domain; a's domain is used).
Curve cross_pcf(const PointSet& a, const PointSet& b, const PcfOptions& opt = {});

// The PCF's r_max for n points in area A: sqrt(2 A / (sqrt(3) n)) (domain units).
double pcf_unit(size_t n, double area = 1.0);

// Mean squared difference of the g values of two curves on the same radii (InputError when
// the radii differ in count).
double curve_mse(const Curve& a, const Curve& b);
// Point-wise mean of curves with the same radii.
Curve mean_curve(const std::vector<Curve>& curves);

}  // namespace ppsynth
