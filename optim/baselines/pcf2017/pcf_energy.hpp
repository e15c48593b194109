#pragma once
// The PCF fitting energy of thesis Eq. 4.3 and its analytic gradient w.r.t. the positions.
//
// The output lives on a torus (the domain, periodic; minimum-image distances). It is covered
// by neighborhoods N_k (disk of center c_k, radius R_k, target intensity lambda_k, target PCF
// t_k sampled at the relative radii of pcf_params.hpp, r_k = rel * r_max(lambda_k)):
//
//   E = sum_k E_k,   E_k = sum_b (g_k(r_b) - t_k(r_b))^2 * d_rel          (Eq. 4.3, discretized)
//   g_k(r) = 1 / (Z_k 2 pi r) * sum_{i in N_k} sum_{j != i} k_s(r - d_ij),   s = sigma_factor r_max(lambda_k)
//
// where j runs over ALL points (the chapter: "each neighborhood should also see points
// belonging to the others; retrieve all points within R_k + r_b"), so no window correction is
// needed and Z_k = lambda_k^2 |N_k| = lambda_k^2 pi R_k^2 (Campbell's theorem). The stationary
// case is one neighborhood covering the whole torus with Z = N (N - 1) / A: then g equals
// pattern_pcf(..., periodic = true) of local_pcf.hpp exactly.
//
// Gradient (u_ij = (x_i - x_j) / d_ij, k' = dk/dt, e_k = g_k - t_k): each ordered pair (i in
// N_k, j) contributes
//   dE/dx_i += phi_k(d_ij) u_ij,   dE/dx_j -= phi_k(d_ij) u_ij,
//   phi_k(d) = - sum_b 2 e_k(r_b) d_rel k'(r_b - d) / (Z_k 2 pi r_b).
// Neighborhood membership (i in N_k) is piecewise constant in the positions and treated as
// fixed, as in the chapter (E jumps when a point crosses a neighborhood border; the
// stationary case has no border).
#include <vector>

#include "core/point_set.hpp"
#include "optim/baselines/pcf2017/pcf_params.hpp"

namespace ppsynth::pcf2017 {

struct Neighborhood {
  Vec2 center;
  double radius = 0;            // R_k; <= 0 means the whole domain (every point is in N_k)
  double lambda = 0;            // target intensity (points per unit area)
  double norm = 0;              // Z_k
  std::vector<double> target;   // t_k at relative_radii(params)
};

// The stationary neighborhood for n points on the whole torus `domain`.
Neighborhood whole_domain_neighborhood(size_t n, const Domain& domain, std::vector<double> target);
// A disk neighborhood with Z = lambda^2 pi R^2.
Neighborhood disk_neighborhood(Vec2 center, double radius, double lambda, std::vector<double> target);

class PcfEnergy {
 public:
  // Throws InputError on impossible parameters or when a neighborhood's pair reach
  // (r_b r_max + cutoff s) exceeds half the torus (minimum-image distances would break).
  PcfEnergy(Domain domain, std::vector<Neighborhood> hoods, PcfParams params = {});

  // E at positions x; fills dE/dx when `grad` is given, the estimated g_k when `curves` is.
  double evaluate(const std::vector<Vec2>& x, std::vector<Vec2>* grad = nullptr,
                  std::vector<std::vector<double>>* curves = nullptr) const;

  const std::vector<Neighborhood>& neighborhoods() const { return hoods_; }
  const Domain& domain() const { return domain_; }
  const PcfParams& params() const { return params_; }

 private:
  Domain domain_;
  std::vector<Neighborhood> hoods_;
  PcfParams params_;
  std::vector<double> rel_;
};

}  // namespace ppsynth::pcf2017
