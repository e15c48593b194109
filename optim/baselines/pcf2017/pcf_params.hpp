#pragma once
// Parameters of the PCF estimator of thesis Chapter 4 (Roveri, Öztireli, Gross 2017), taken
// from Öztireli & Gross 2012 as Section 4.2.4 states them. Every length is relative to
//
//   r_max = sqrt(2 A / (sqrt(3) N))   [length units of the domain]
//
// "the minimum distance between pairs of points for the maximum (hexagonal) packing" of N
// points in area A (= 2x the Lagae-Dutré disk radius sqrt(A / (2 sqrt(3) N))). For a local
// neighborhood of intensity lambda, A/N is replaced by 1/lambda.
//
// The PCF is sampled at `bins` radii evenly spaced in [r_a, r_b] * r_max (defaults: 100
// samples in [0.01, 2.5] r_max), smoothed with the 1D normalized Gaussian of the chapter,
//
//   k_s(t) = exp(-t^2 / s^2) / (sqrt(pi) s),     s = sigma_factor * r_max (default 0.25)
//
// (note: s is sqrt(2) times the standard deviation; this is the chapter's convention for
// both the intensity and the PCF kernels). Header-only: tiny inline helpers.
#include <cmath>
#include <vector>

namespace ppsynth::pcf2017 {

struct PcfParams {
  int bins = 100;             // samples of ||h||
  double r_a = 0.01;          // lower PCF limit, in units of r_max
  double r_b = 2.5;           // upper PCF limit, in units of r_max
  double sigma_factor = 0.25; // kernel width s / r_max
  double kernel_cutoff = 4.0; // pairs/bins farther than cutoff * s apart are skipped (exp(-16))
};

// r_max for `n` points in area `area` (or for intensity lambda: rmax_for_intensity).
inline double rmax_for(double n, double area) { return std::sqrt(2.0 * area / (std::sqrt(3.0) * n)); }
inline double rmax_for_intensity(double lambda) { return std::sqrt(2.0 / (std::sqrt(3.0) * lambda)); }

// The radii r_a..r_b (units of r_max), `bins` samples including both ends.
inline std::vector<double> relative_radii(const PcfParams& p) {
  std::vector<double> r(p.bins);
  const double step = p.bins > 1 ? (p.r_b - p.r_a) / (p.bins - 1) : 0.0;
  for (int b = 0; b < p.bins; ++b) r[b] = p.r_a + step * b;
  return r;
}
// Spacing of relative_radii (the dr of the discretized integral of Eq. 4.3).
inline double relative_step(const PcfParams& p) { return p.bins > 1 ? (p.r_b - p.r_a) / (p.bins - 1) : 1.0; }

// k_s(t) and its derivative dk/dt = -2 t / s^2 k_s(t).
inline double kernel(double t, double s) {
  static const double inv_sqrt_pi = 1.0 / std::sqrt(M_PI);
  return std::exp(-t * t / (s * s)) * inv_sqrt_pi / s;
}
inline double kernel_derivative(double t, double s) { return -2.0 * t / (s * s) * kernel(t, s); }

// A sampled PCF: g[b] at radius r[b] (absolute length units) = rel[b] * r_max.
struct PcfCurve {
  std::vector<double> r;    // absolute radii
  std::vector<double> rel;  // radii / r_max
  std::vector<double> g;
  double r_max = 0;
};

// Mean squared difference of two curves sampled at the same relative radii.
double curve_mse(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace ppsynth::pcf2017
