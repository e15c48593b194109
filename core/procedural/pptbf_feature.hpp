#pragma once
// PPTBF feature function F (supplement step [7]): per cell, J "stringed Gabor" kernels whose
// random parameters come from seeding2(p) (kFeature stream), in this draw order per kernel:
// prior, valb (both U[-1,1)), mu (U over the cell, 2 draws), theta = deltaorient * U[0,1),
// sigb = sigcos * (1 + sigcosvar * U[0,1)). The window stream seeding(p) gives the Bezier
// start angle (nv step * U[0,1)) then J = Jmin + floor((Jmax - Jmin + 1) U[0,1)).
//
// Kernel j at x, with d the cell size and eta, kappa, phi, tau, ||.||_f from PptbfParams:
//   mu  = mix(mu_random, p, winfeatcorrel)              (correl 1: kernels on the point)
//   dd  = R(theta) (x - mu) / d,  dd.y /= eta
//   ff  = (0.5 + 0.5 cos(pi phi sqrt(kappa^2 dd.x^2 + dd.y^2)))^(1 / (tau + 1e-4))
//   fdist = ||dd||_f / (footprint / sigb)
// Mixture models (Fig. 2; numbering of the pseudo-code):
//   1 sum of ff A exp(-fdist), A = valb mapped to +-[0.25, 1]; then 0.5 F + 0.5
//   2 sum of ff exp(-fdist), divided by J (normalized sum)
//   3 1 - sum of ff exp(-fdist) (features carved into the window)
//   4 random-priority bombing: over all cells and kernels with fdist < 1 and ff > 0.5, the
//     kernel with the highest prior gives 2 (ff - 0.5) exp(-fdist)  (window not used)
//   5 max: the largest ff exp(-fdist) over all cells and kernels  (window not used)
//   0 constant feature 1 (window only; the pseudo-code's default case)
#include <vector>

#include "core/procedural/pptbf_params.hpp"
#include "core/procedural/pptbf_tiling.hpp"

namespace ppsynth::pptbf_impl {

struct Kernel {
  double prior = 0, valb = 0;
  Vec2 mu;
  double cos_t = 1, sin_t = 0;
  double sigb = 1;
};

struct CellFeature {
  double start_angle = 0;  // Bezier polygon start angle (window stream)
  int J = 0;
  std::vector<Kernel> kernels;
};

// All random numbers of one cell (seeding and seeding2 of the pseudo-code).
CellFeature draw_cell_feature(const FeaturePoint& fp, const PptbfParams& prm);

struct KernelValue {
  double ff = 0, fdist = 0;
};
KernelValue eval_kernel(const Kernel& k, const FeaturePoint& fp, Vec2 x, const PptbfParams& prm,
                        double footprint);

// Feature value of one cell for the sum models (mixture 0..3).
double feature_sum(const CellFeature& cf, const FeaturePoint& fp, Vec2 x, const PptbfParams& prm,
                   double footprint);

// Running state of the max models (mixture 4, 5) over all cells of one pixel.
struct MaxMixture {
  double priomax = -1.0;   // mixture 4
  double minval = -1000.0; // mixture 5
  double value = 0.0;
  void add_cell(const CellFeature& cf, const FeaturePoint& fp, Vec2 x, const PptbfParams& prm,
                double footprint);
};

}  // namespace ppsynth::pptbf_impl
