#include "core/metrics/spectrum.hpp"

#include <cmath>
#include <complex>

#include "core/error.hpp"

namespace ppsynth {

Spectrum power_spectrum(const PointSet& ps, int F) {
  if (F < 1) throw InputError("power_spectrum: max_frequency must be >= 1");
  if (ps.empty()) throw InputError("power_spectrum: empty point set");
  const Domain& d = ps.domain();
  const int S = 2 * F + 1;
  const size_t n = ps.size();
  using C = std::complex<double>;
  // ex[j*S + (f+F)] = exp(-2 pi i f u_j), likewise ey.
  std::vector<C> ex(n * S), ey(n * S);
  for (size_t j = 0; j < n; ++j) {
    const double u = (ps[j].x - d.x0) / d.width(), v = (ps[j].y - d.y0) / d.height();
    for (int f = -F; f <= F; ++f) {
      ex[j * S + f + F] = std::polar(1.0, -2 * M_PI * f * u);
      ey[j * S + f + F] = std::polar(1.0, -2 * M_PI * f * v);
    }
  }
  Spectrum s;
  s.image.width = s.image.height = S;
  s.image.pixels.assign(static_cast<size_t>(S) * S, 0.f);
  std::vector<C> row(S);
  for (int fy = 0; fy < S; ++fy) {
    std::fill(row.begin(), row.end(), C(0, 0));
    for (size_t j = 0; j < n; ++j) {
      const C wy = ey[j * S + fy];
      const C* wx = &ex[j * S];
      for (int fx = 0; fx < S; ++fx) row[fx] += wx[fx] * wy;
    }
    for (int fx = 0; fx < S; ++fx)
      s.image.pixels[static_cast<size_t>(fy) * S + fx] = static_cast<float>(std::norm(row[fx]) / n);
  }
  std::vector<double> sum(F + 1, 0), sum2(F + 1, 0);
  std::vector<size_t> cnt(F + 1, 0);
  for (int fy = -F; fy <= F; ++fy)
    for (int fx = -F; fx <= F; ++fx) {
      const long k = std::lround(std::hypot(fx, fy));
      if (k > F) continue;
      const double p = s.image.pixels[static_cast<size_t>(fy + F) * S + fx + F];
      sum[k] += p;
      sum2[k] += p * p;
      ++cnt[k];
    }
  for (int k = 0; k <= F; ++k) {
    s.frequency.push_back(k);
    const double mean = sum[k] / cnt[k];
    const double var = std::max(0.0, sum2[k] / cnt[k] - mean * mean);
    s.radial_power.push_back(mean);
    s.anisotropy.push_back(k == 0 || mean <= 0 ? 0.0 : var / (mean * mean));
  }
  return s;
}

}  // namespace ppsynth
