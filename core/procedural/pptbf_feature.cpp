#include "core/procedural/pptbf_feature.hpp"

#include <cmath>

#include "core/procedural/pptbf_random.hpp"
#include "core/procedural/pptbf_window.hpp"

namespace ppsynth::pptbf_impl {

namespace {
std::int64_t key_ab(const CellKey& k) { return k.part * 64 + k.sub; }
}  // namespace

CellFeature draw_cell_feature(const FeaturePoint& fp, const PptbfParams& prm) {
  const auto seed = static_cast<std::uint64_t>(prm.seed);
  CellFeature cf;
  CellRng win(seed, kStreamWindow, fp.key.i, fp.key.j, key_ab(fp.key));
  cf.start_angle = (2 * M_PI / prm.arity) * win.rand01();
  cf.J = prm.Jmin + static_cast<int>(std::floor((prm.Jmax - prm.Jmin + 1) * win.rand01()));
  if (cf.J > prm.Jmax) cf.J = prm.Jmax;
  CellRng feat(seed, kStreamFeature, fp.key.i, fp.key.j, key_ab(fp.key));
  cf.kernels.resize(cf.J);
  for (Kernel& k : cf.kernels) {
    k.prior = feat.rand();
    k.valb = feat.rand();
    const double ux = feat.rand(), uy = feat.rand();
    const Vec2 mu_random{fp.c.x + (0.5 + 0.5 * ux) * fp.d.x, fp.c.y + (0.5 + 0.5 * uy) * fp.d.y};
    const double t = prm.winfeatcorrel;
    k.mu = {(1 - t) * mu_random.x + t * fp.p.x, (1 - t) * mu_random.y + t * fp.p.y};
    const double theta = prm.deltaorient * feat.rand01();
    k.cos_t = std::cos(theta);
    k.sin_t = std::sin(theta);
    k.sigb = prm.sigcos * (1.0 + prm.sigcosvar * feat.rand01());
  }
  return cf;
}

namespace {
// dd of the pseudo-code and its feature-norm distance
Vec2 kernel_frame(const Kernel& k, const FeaturePoint& fp, Vec2 x, const PptbfParams& prm) {
  const Vec2 dif{(x.x - k.mu.x) / fp.d.x, (x.y - k.mu.y) / fp.d.y};
  Vec2 dd{k.cos_t * dif.x - k.sin_t * dif.y, k.sin_t * dif.x + k.cos_t * dif.y};
  dd.y /= prm.feataniso;
  return dd;
}
double stripes(Vec2 dd, const PptbfParams& prm) {
  if (prm.freq == 0) return 1.0;  // cos(0) = 1: no stripes
  const double xfeat = std::sqrt(dd.x * dd.x * prm.curvature * prm.curvature + dd.y * dd.y);
  const double ff = 0.5 + 0.5 * std::cos(M_PI * prm.freq * xfeat);
  return std::pow(ff, 1.0 / (0.0001 + prm.thickness));
}
}  // namespace

KernelValue eval_kernel(const Kernel& k, const FeaturePoint& fp, Vec2 x, const PptbfParams& prm,
                        double footprint) {
  const Vec2 dd = kernel_frame(k, fp, x, prm);
  KernelValue v;
  v.ff = stripes(dd, prm);
  v.fdist = minkowski(dd, prm.normfeat) / (footprint / k.sigb);
  return v;
}

double feature_sum(const CellFeature& cf, const FeaturePoint& fp, Vec2 x, const PptbfParams& prm,
                   double footprint) {
  if (prm.mixture == 0) return 1.0;
  double feat = 0;
  for (const Kernel& k : cf.kernels) {
    const KernelValue v = eval_kernel(k, fp, x, prm, footprint);
    if (prm.mixture == 1) {
      const double amp = k.valb < 0.0 ? -0.25 + 0.75 * k.valb : 0.25 + 0.75 * k.valb;
      feat += v.ff * amp * std::exp(-v.fdist);
    } else {
      feat += v.ff * std::exp(-v.fdist);
    }
  }
  if (prm.mixture == 1) feat = 0.5 * feat + 0.5;
  if (prm.mixture == 2) feat = cf.J > 0 ? feat / cf.J : 0.0;
  if (prm.mixture == 3) feat = 1.0 - feat;
  return feat;
}

void MaxMixture::add_cell(const CellFeature& cf, const FeaturePoint& fp, Vec2 x, const PptbfParams& prm,
                          double footprint) {
  for (const Kernel& k : cf.kernels) {
    const Vec2 dd = kernel_frame(k, fp, x, prm);
    const double fdist = minkowski(dd, prm.normfeat) / (footprint / k.sigb);
    if (prm.mixture == 4) {
      if (!(priomax < k.prior && fdist < 1.0)) continue;
      const double ff = stripes(dd, prm);
      if (ff > 0.5) {
        priomax = k.prior;
        value = 2.0 * (ff - 0.5) * std::exp(-fdist);
      }
    } else {  // mixture 5; ff <= 1 so exp(-fdist) bounds the kernel value
      const double bound = std::exp(-fdist);
      if (bound <= minval) continue;
      const double ww = stripes(dd, prm) * bound;
      if (minval < ww) {
        value = ww;
        minval = ww;
      }
    }
  }
}

}  // namespace ppsynth::pptbf_impl
