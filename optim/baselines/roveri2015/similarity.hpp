#pragma once
// Neighborhood similarity of thesis Eq. 3.2 / 3.5 / A.6 and the sampling error of Eq. 3.7,
// with analytic gradients (Appendix A.1.2; the appendix's equations are missing from the
// text, they are re-derived in docs/explanation/roveri2015.md and checked against finite differences in
// tests/optim/baselines/test_roveri2015.cpp).
//
// A neighborhood is given by the points near its center as RELATIVE positions: output
// points u_i = x_i - q (around a quadrature point q) with channels a_i, exemplar points
// v_j = e_j - m (around its match m) with channels b_j. With c = the normalizing constant
// below, the similarity error density S = (1/c) Int |f(q+s) - e(m+s)|^2 w(s) ds is
//
//   S = sum_ij (a_i.a_j) P(u_i,u_j) - 2 sum_ij (a_i.b_j) P(u_i,v_j) + sum_ij (b_i.b_j) P(v_i,v_j)
//   P(p, r) = G(p - r) W(p + r),   G(h) = exp(-|h|^2 / (2 sigma^2))  (= g(h, sqrt(2) sigma))
//
//   box window (Eq. 3.5):     W = 1, c = pi sigma^2 / 2, points within delta of q / m only;
//   Gaussian window (A.6):    w(s) = exp(-|s|^2/delta^2),  W(h) = exp(-|h|^2 / (2 tau^2)),
//                             tau^2 = sigma^2 + 2 delta^2,  c = pi sigma^2 delta^2 / tau^2,
//                             points within window_cutoff * delta only.
// S >= 0 (an integral of a square), S = 0 for identical neighborhoods; dimensionless
// (squared channel values). Derivatives, with dP/dp = P (-(p-r)/sigma^2 - (p+r)/tau^2) and
// dP/dr = P ((p-r)/sigma^2 - (p+r)/tau^2) (1/tau^2 = 0 for the box):
//   dS/dx_i = dS/du_i,   dS/dm = -sum_j dS/dv_j,   dS/da_i = 2 sum_j a_j P(u_i,u_j) - 2 sum_j b_j P(u_i,v_j).
//
// Sampling error density (Eq. 3.7, a_i = b_i = 1), normalized by one Gaussian's mass pi sigma^2
// so that it counts points: P_s = (1/(pi sigma^2)) Int (f(q+s) - e(m+s)) w(s) ds
//   box:       n_out - n_ex  (points inside the window)
//   Gaussian:  kappa [sum_i exp(-|u_i|^2/(sigma^2+delta^2)) - sum_j exp(-|v_j|^2/(sigma^2+delta^2))],
//              kappa = delta^2 / (sigma^2 + delta^2).
// P_s < 0: the output has fewer points than the matched exemplar window (add one); P_s > 0: more.
#include <cstddef>
#include <vector>

#include "core/point_set.hpp"
#include "optim/baselines/roveri2015/params.hpp"

namespace ppsynth::roveri2015 {

// Points of one neighborhood: relative positions, channel vectors (D each), and the index
// of each point in its set (for scattering gradients back).
struct Neighborhood {
  std::vector<Vec2> rel;
  std::vector<const double*> a;
  std::vector<size_t> index;
  size_t size() const { return rel.size(); }
  void clear() { rel.clear(); a.clear(); index.clear(); }
  void push(Vec2 r, const double* ch, size_t i) { rel.push_back(r); a.push_back(ch); index.push_back(i); }
};

// Which terms to evaluate. Matching does not need the output-output term (constant in m),
// merging does not need the exemplar-exemplar term (constant in x_i, a_i).
struct SimilarityTerms {
  bool out_out = true;
  bool ex_ex = true;
};

// Gradients (optional, each filled when its pointer is non-null; resized by the call).
struct SimilarityGrad {
  std::vector<Vec2>* d_out = nullptr;     // dS/du_i (= dS/dx_i)
  std::vector<Vec2>* d_ex = nullptr;      // dS/dv_j (dS/dm = -sum)
  std::vector<double>* d_attr = nullptr;  // dS/da_i, D per output point
};

double similarity(const Neighborhood& out, const Neighborhood& ex, int D, const KernelParams& kp,
                  SimilarityTerms terms = {}, const SimilarityGrad& grad = {});

// dS/dm from the exemplar gradient: -sum_j dS/dv_j.
Vec2 match_gradient(const std::vector<Vec2>& d_ex);

// Sampling error density P_s of Eq. 3.7 (see above; counts of points, signed out - ex).
double sampling_error(const Neighborhood& out, const Neighborhood& ex, const KernelParams& kp);

// Relative position b - a: plain difference, or the minimum image on the torus `d`.
Vec2 relative(Vec2 a, Vec2 b, const Domain& d, bool periodic);

}  // namespace ppsynth::roveri2015
