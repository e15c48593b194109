#include "core/metrics/subwindow_spread.hpp"

#include <cmath>
#include <random>

#include "core/metrics/summary_stats.hpp"

namespace ppsynth {

std::vector<Domain> random_subwindows(const Domain& d, double side, int count, uint64_t seed) {
  const double w = side * d.width(), h = side * d.height();
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 0x5851F42D4C957F2Dull);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Domain> windows;
  windows.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double x0 = d.x0 + u(rng) * (d.width() - w), y0 = d.y0 + u(rng) * (d.height() - h);
    windows.push_back(Domain{x0, y0, x0 + w, y0 + h});
  }
  return windows;
}

double spread_scale(double sub_area, double exemplar_area, double output_area) {
  return std::sqrt((1 / output_area + 1 / exemplar_area) / (1 / sub_area - 1 / exemplar_area));
}

Spread spread_of(const std::vector<double>& scaled) {
  Spread s;
  for (double v : scaled)
    if (std::isfinite(v)) ++s.draws;
  if (s.draws > 0) s.median = quantile(scaled, 0.5);
  return s;
}

}  // namespace ppsynth
