#pragma once
// The smooth PCF estimator of thesis Eq. 4.1 (after Illian et al. 2008 / Öztireli & Gross
// 2012), for a window N_x (2D, so |dV_2| = 2 pi, the unit circle's length):
//
//   g_x(r) = 1 / (lambda^2 2 pi r) * sum_{i != j in N_x} k_s(r - ||h_ij||) / a_N(h_ij)
//
// over ordered pairs, h_ij = x_i - x_j, k_s the 1D Gaussian of pcf_params.hpp, and a_N(h) the
// autocorrelation of N_x's indicator (area of N_x intersected with N_x shifted by h):
//   - disk of radius R inside the domain (or periodic): 2R^2 acos(t/2R) - t/2 sqrt(4R^2 - t^2)
//   - disk clipped by a non-periodic border: integrated numerically on a grid
//   - the whole rectangle W x H: (W - |h_x|)(H - |h_y|);  the whole torus: W H.
// Radii are sampled relative to the window's r_max (pcf_params.hpp), so curves of patterns
// with different densities are comparable (the chapter's density normalization).
//
// Known property of this estimator (not a bug): for r below ~3 s the kernel mass at negative
// distances is missing and the 1/r factor inflates g (a Poisson pattern gives g(0.01 r_max)
// ~ 7); only r >~ 0.75 r_max is unbiased. Synthesis compares curves made by the same estimator,
// so the bias cancels.
#include <vector>

#include "core/point_set.hpp"
#include "optim/baselines/pcf2017/local_intensity.hpp"
#include "optim/baselines/pcf2017/pcf_params.hpp"

namespace ppsynth::pcf2017 {

// PCF of the whole pattern (the stationary case): window = the domain (torus when
// `periodic` or the domain says so), lambda^2 = N (N - 1) / A^2 (exact for N uniform points),
// r_max = rmax_for(N, A).
PcfCurve pattern_pcf(const PointSet& ps, const PcfParams& params = {}, bool periodic = false);

struct LocalPcfOptions {
  PcfParams pcf;
  // Neighborhood size as an expected point count m: R_x = sqrt(m / (pi lambda_x)) (the
  // chapter fixes the number of points per neighborhood). Ignored when radius > 0.
  double neighborhood_points = 60;
  double radius = 0;             // fixed R in domain units (0 = from neighborhood_points)
  IntensityOptions intensity;    // kernel density at x (local_intensity.hpp): sizes N_x
  // lambda in Eq. 4.1 (and r_max): true = k / |N_x| from the k points in the window, with
  // lambda^2 = k (k - 1) / |N_x|^2 (exact for uniform points; far less noisy than the kernel
  // estimate, whose error enters squared); false = the kernel estimate, as the chapter writes.
  bool lambda_from_count = true;
  bool periodic = false;         // or'ed with the domain's flag
  int window_samples = 40;       // grid per axis for clipped-disk autocorrelations
};

// Eq. 4.1 at one query position; r_max = rmax_for_intensity(lambda) (see lambda_from_count).
PcfCurve local_pcf(const PointSet& ps, Vec2 x, const LocalPcfOptions& opt = {});
// Eq. 4.1 at several query positions (lambda_x computed once for all).
std::vector<PcfCurve> local_pcfs(const PointSet& ps, const std::vector<Vec2>& queries,
                                 const LocalPcfOptions& opt = {});

// Area of the intersection of two disks of radius R whose centers are t apart.
double disk_autocorrelation(double R, double t);

}  // namespace ppsynth::pcf2017
