#include "optim/baselines/roveri2015/similarity.hpp"

#include <cmath>

namespace ppsynth::roveri2015 {

namespace {

inline double dot(const double* a, const double* b, int D) {
  double s = 0;
  for (int d = 0; d < D; ++d) s += a[d] * b[d];
  return s;
}

// One pair term P(p, r) = G(p - r) W(p + r) and its partial derivatives.
struct PairKernel {
  double inv_s2;     // 1 / sigma^2
  double inv_2s2;    // 1 / (2 sigma^2)
  double inv_t2;     // 1 / tau^2 (0 for the box window)
  double inv_2t2;
  double cut2;       // pairs with |p - r|^2 > cut2 are skipped
  explicit PairKernel(const KernelParams& kp) {
    const double s2 = kp.sigma * kp.sigma;
    inv_s2 = 1.0 / s2;
    inv_2s2 = 0.5 / s2;
    if (kp.window == WindowKind::Gaussian) {
      const double t2 = s2 + 2.0 * kp.delta * kp.delta;
      inv_t2 = 1.0 / t2;
      inv_2t2 = 0.5 / t2;
    } else {
      inv_t2 = inv_2t2 = 0;
    }
    const double c = kp.pair_cutoff * kp.sigma;
    cut2 = c * c;
  }
  // Returns P (0 when cut); fills dp = dP/dp, dr = dP/dr when `deriv`.
  inline double eval(Vec2 p, Vec2 r, bool deriv, Vec2& dp, Vec2& dr) const {
    const double hx = p.x - r.x, hy = p.y - r.y;
    const double h2 = hx * hx + hy * hy;
    if (h2 > cut2) return 0;
    const double sx = p.x + r.x, sy = p.y + r.y;
    const double v = std::exp(-h2 * inv_2s2 - (sx * sx + sy * sy) * inv_2t2);
    if (deriv) {
      dp = {v * (-hx * inv_s2 - sx * inv_t2), v * (-hy * inv_s2 - sy * inv_t2)};
      dr = {v * (hx * inv_s2 - sx * inv_t2), v * (hy * inv_s2 - sy * inv_t2)};
    }
    return v;
  }
};

// sum_ij (c_i.c_j) P(w_i, w_j) over one set, with dS/dw and (optionally) dS/dc.
double self_term(const Neighborhood& s, int D, const PairKernel& k, std::vector<Vec2>* dw,
                 std::vector<double>* dc) {
  const size_t n = s.size();
  const bool deriv = dw != nullptr;
  double total = 0;
  Vec2 dp, dr;
  for (size_t i = 0; i < n; ++i) {
    // Diagonal: P(w, w) = W(2w), d/dw = -4 w / tau^2 W(2w).
    {
      const double v = k.eval(s.rel[i], s.rel[i], false, dp, dr);
      const double aa = dot(s.a[i], s.a[i], D);
      total += aa * v;
      if (deriv) {
        (*dw)[i].x += aa * v * (-4.0 * s.rel[i].x * k.inv_t2);
        (*dw)[i].y += aa * v * (-4.0 * s.rel[i].y * k.inv_t2);
      }
      if (dc)
        for (int d = 0; d < D; ++d) (*dc)[i * D + d] += 2.0 * s.a[i][d] * v;
    }
    for (size_t j = i + 1; j < n; ++j) {
      const double v = k.eval(s.rel[i], s.rel[j], deriv, dp, dr);
      if (v == 0) continue;
      const double aa = dot(s.a[i], s.a[j], D);
      total += 2.0 * aa * v;
      if (deriv) {
        (*dw)[i].x += 2.0 * aa * dp.x;
        (*dw)[i].y += 2.0 * aa * dp.y;
        (*dw)[j].x += 2.0 * aa * dr.x;
        (*dw)[j].y += 2.0 * aa * dr.y;
      }
      if (dc)
        for (int d = 0; d < D; ++d) {
          (*dc)[i * D + d] += 2.0 * s.a[j][d] * v;
          (*dc)[j * D + d] += 2.0 * s.a[i][d] * v;
        }
    }
  }
  return total;
}

}  // namespace

double similarity(const Neighborhood& out, const Neighborhood& ex, int D, const KernelParams& kp,
                  SimilarityTerms terms, const SimilarityGrad& grad) {
  const PairKernel k(kp);
  const bool deriv = grad.d_out || grad.d_ex;
  std::vector<Vec2> tmp_out, tmp_ex;
  std::vector<Vec2>* d_out = grad.d_out ? grad.d_out : (deriv ? &tmp_out : nullptr);
  std::vector<Vec2>* d_ex = grad.d_ex ? grad.d_ex : (deriv ? &tmp_ex : nullptr);
  if (d_out) d_out->assign(out.size(), Vec2{0, 0});
  if (d_ex) d_ex->assign(ex.size(), Vec2{0, 0});
  if (grad.d_attr) grad.d_attr->assign(out.size() * size_t(D), 0.0);

  double S = 0;
  if (terms.out_out) S += self_term(out, D, k, d_out, grad.d_attr);
  if (terms.ex_ex) S += self_term(ex, D, k, d_ex, nullptr);
  Vec2 dp, dr;
  for (size_t i = 0; i < out.size(); ++i) {
    for (size_t j = 0; j < ex.size(); ++j) {
      const double v = k.eval(out.rel[i], ex.rel[j], deriv, dp, dr);
      if (v == 0) continue;
      const double ab = dot(out.a[i], ex.a[j], D);
      S -= 2.0 * ab * v;
      if (deriv) {
        (*d_out)[i].x -= 2.0 * ab * dp.x;
        (*d_out)[i].y -= 2.0 * ab * dp.y;
        (*d_ex)[j].x -= 2.0 * ab * dr.x;
        (*d_ex)[j].y -= 2.0 * ab * dr.y;
      }
      if (grad.d_attr)
        for (int d = 0; d < D; ++d) (*grad.d_attr)[i * D + d] -= 2.0 * ex.a[j][d] * v;
    }
  }
  return S;
}

Vec2 match_gradient(const std::vector<Vec2>& d_ex) {
  Vec2 g{0, 0};
  for (const Vec2& d : d_ex) {
    g.x -= d.x;
    g.y -= d.y;
  }
  return g;
}

double sampling_error(const Neighborhood& out, const Neighborhood& ex, const KernelParams& kp) {
  if (kp.window == WindowKind::Box) return double(out.size()) - double(ex.size());
  const double s2 = kp.sigma * kp.sigma, d2 = kp.delta * kp.delta;
  const double inv = 1.0 / (s2 + d2);
  double P = 0;
  for (const Vec2& u : out.rel) P += std::exp(-(u.x * u.x + u.y * u.y) * inv);
  for (const Vec2& v : ex.rel) P -= std::exp(-(v.x * v.x + v.y * v.y) * inv);
  return P * d2 * inv;
}

Vec2 relative(Vec2 a, Vec2 b, const Domain& d, bool periodic) {
  double dx = b.x - a.x, dy = b.y - a.y;
  if (periodic) {
    const double W = d.width(), H = d.height();
    dx -= W * std::round(dx / W);
    dy -= H * std::round(dy / H);
  }
  return {dx, dy};
}

}  // namespace ppsynth::roveri2015
