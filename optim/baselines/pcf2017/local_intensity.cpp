#include "optim/baselines/pcf2017/local_intensity.hpp"

#include <cmath>

#include "core/error.hpp"
#include "optim/baselines/pcf2017/pcf_params.hpp"

namespace ppsynth::pcf2017 {

namespace {
// Gaussian mass exp(-t^2/s^2)/(sqrt(pi) s) over [a, b].
double mass_1d(double a, double b, double s) { return 0.5 * (std::erf(b / s) - std::erf(a / s)); }
}  // namespace

double intensity_sigma(const PointSet& ps, const IntensityOptions& opt) {
  if (opt.sigma > 0) return opt.sigma;
  if (ps.empty()) throw InputError("local intensity: empty point set");
  if (!(opt.sigma_rmax > 0)) throw InputError("local intensity: sigma_rmax must be > 0");
  return opt.sigma_rmax * rmax_for(double(ps.size()), ps.domain().area());
}

std::vector<double> local_intensity(const PointSet& ps, const std::vector<Vec2>& queries,
                                    const IntensityOptions& opt) {
  const double s = intensity_sigma(ps, opt);
  const Domain& d = ps.domain();
  const bool periodic = opt.periodic || d.periodic;
  const double norm = 1.0 / (M_PI * s * s), cut2 = 36.0 * s * s;
  std::vector<double> out(queries.size(), 0.0);
  for (size_t q = 0; q < queries.size(); ++q) {
    const Vec2 x = queries[q];
    double sum = 0;
    for (const Vec2& p : ps.positions()) {
      double dx = x.x - p.x, dy = x.y - p.y;
      if (periodic) {
        dx -= d.width() * std::round(dx / d.width());
        dy -= d.height() * std::round(dy / d.height());
      }
      const double r2 = dx * dx + dy * dy;
      if (r2 < cut2) sum += std::exp(-r2 / (s * s));
    }
    double inside = 1.0;
    if (!periodic && opt.edge_correct)
      inside = mass_1d(d.x0 - x.x, d.x1 - x.x, s) * mass_1d(d.y0 - x.y, d.y1 - x.y, s);
    out[q] = sum * norm / std::max(inside, 1e-12);
  }
  return out;
}

std::vector<double> intensity_map(const PointSet& ps, int width, int height,
                                  const IntensityOptions& opt) {
  if (width <= 0 || height <= 0) throw InputError("intensity map: size must be positive");
  const Domain& d = ps.domain();
  std::vector<Vec2> q;
  q.reserve(size_t(width) * height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      q.push_back({d.x0 + (i + 0.5) * d.width() / width, d.y0 + (j + 0.5) * d.height() / height});
  return local_intensity(ps, q, opt);
}

}  // namespace ppsynth::pcf2017
