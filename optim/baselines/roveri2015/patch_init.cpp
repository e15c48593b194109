#include "optim/baselines/roveri2015/patch_init.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "core/error.hpp"

namespace ppsynth::roveri2015 {

PointSet random_patch_copy(const PointSet& exemplar, const Domain& out_domain, double patch_side, uint64_t seed) {
  const Domain& E = exemplar.domain();
  if (!(patch_side > 0)) throw InputError("roveri2015: patch size must be > 0");
  const double side = std::min({patch_side, E.width(), E.height()});
  const int nx = std::max(1, int(std::lround(out_domain.width() / side)));
  const int ny = std::max(1, int(std::lround(out_domain.height() / side)));
  const double pw = std::min(out_domain.width() / nx, E.width());
  const double ph = std::min(out_domain.height() / ny, E.height());
  PointSet out(out_domain);
  for (const std::string& name : exemplar.attribute_names()) out.add_attribute(name);
  out.set_class_labels(exemplar.class_labels());
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(E.x0, E.x1 - pw), uy(E.y0, E.y1 - ph);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double cx = out_domain.x0 + i * out_domain.width() / nx;
      const double cy = out_domain.y0 + j * out_domain.height() / ny;
      const double sx = pw < E.width() ? ux(rng) : E.x0;
      const double sy = ph < E.height() ? uy(rng) : E.y0;
      for (size_t p = 0; p < exemplar.size(); ++p) {
        const Vec2 e = exemplar[p];
        if (e.x < sx || e.x >= sx + pw || e.y < sy || e.y >= sy + ph) continue;
        out.add({cx + (e.x - sx), cy + (e.y - sy)}, exemplar.cls(p), exemplar.attributes_of(p));
      }
    }
  return out;
}

}  // namespace ppsynth::roveri2015
