#include "core/metrics/second_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>


namespace ppsynth {

double spatstat_r_max(const Domain& w, double lambda) {
  const double ripley = std::min(w.width(), w.height()) / 4.0;
  const double large = lambda > 0 ? std::sqrt(1000.0 / (M_PI * lambda)) : std::numeric_limits<double>::infinity();
  return std::min(ripley, large);
}

std::vector<double> spatstat_r_grid(const Domain& w, double lambda) {
  // handle.r.b.args: pixeps = r_max / 128, step = pixeps / 4; make.even.breaks: ceiling(r_max /
  // step) steps up to step * steps, laid as R's seq(0, right, length.out) (the last value exact).
  const double rmax = spatstat_r_max(w, lambda);
  const double step = rmax / 128.0 / 4.0;
  const auto n = static_cast<size_t>(std::ceil(rmax / step));
  const double right = step * static_cast<double>(n);
  const double by = right / static_cast<double>(n);
  std::vector<double> r(n + 1);
  for (size_t k = 0; k < n; ++k) r[k] = static_cast<double>(k) * by;
  r[n] = right;
  return r;
}

SecondOrder second_order(const PointSet& a, const PointSet* b, EdgeCorrection c, std::vector<double> r, bool with_g) {
  const Domain& w = a.domain();
  const double area = w.area();
  const PointSet& second = b ? *b : a;
  const double lambda = static_cast<double>(second.size()) / area;
  if (r.empty()) r = spatstat_r_grid(w, lambda);
  SecondOrder s;
  s.r = r;
  s.bandwidth = lambda > 0 ? kStoyan / std::sqrt(lambda) : 0;
  const size_t R = r.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double pairs_total = b ? static_cast<double>(a.size()) * static_cast<double>(b->size())
                               : static_cast<double>(a.size()) * (static_cast<double>(a.size()) - 1.0);
  if (!(pairs_total > 0) || R == 0) {
    s.k.assign(R, nan);
    s.l.assign(R, nan);
    if (with_g) s.g.assign(R, nan);
    return s;
  }
  const double h = s.bandwidth;
  const double reach = r.back() + (with_g ? h : 0.0);
  std::vector<double> hist(R, 0.0), kern(R, 0.0);
  // An even grid (the default and any spatstat takes for g): the kernel's bins by index.
  const double step = R > 1 ? (r.back() - r.front()) / static_cast<double>(R - 1) : 1.0;
  for_each_close_pair(a, b, reach, [&](size_t i, size_t j, double d) {
    const double e = edge_weight(c, w, a[i], second[j], d);
    if (d <= r.back()) hist[static_cast<size_t>(std::lower_bound(r.begin(), r.end(), d) - r.begin())] += e;
    if (!with_g) return;
    const double lo = (d - h - r.front()) / step, hi = (d + h - r.front()) / step;
    const long k0 = std::max(0L, static_cast<long>(std::floor(lo))), k1 = std::min(static_cast<long>(R) - 1, static_cast<long>(std::ceil(hi)));
    for (long k = k0; k <= k1; ++k) {
      const double t = (r[static_cast<size_t>(k)] - d) / h;
      if (std::abs(t) < 1.0) kern[static_cast<size_t>(k)] += e * 0.75 * (1.0 - t * t) / h;
    }
  });
  const double scale = area / pairs_total;
  s.k.resize(R);
  s.l.resize(R);
  double cum = 0;
  for (size_t k = 0; k < R; ++k) {
    cum += hist[k];
    s.k[k] = scale * cum;
    s.l[k] = std::sqrt(s.k[k] / M_PI);
  }
  if (with_g) {
    s.g.resize(R);
    for (size_t k = 0; k < R; ++k) s.g[k] = r[k] > 0 ? scale * kern[k] / (2.0 * M_PI * r[k]) : nan;
  }
  return s;
}

}  // namespace ppsynth
