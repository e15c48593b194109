#include "core/metrics/border.hpp"

#include <algorithm>
#include <cmath>

namespace ppsynth {

double border_band(const Domain& d) { return kBorderBand * std::min(d.width(), d.height()); }

double border_fraction(const PointSet& ps) {
  if (ps.size() == 0) return std::nan("");
  const Domain& d = ps.domain();
  const double b = border_band(d);
  size_t near = 0;
  for (const Vec2& p : ps.positions())
    if (p.x < d.x0 + b || p.x > d.x1 - b || p.y < d.y0 + b || p.y > d.y1 - b) ++near;
  return static_cast<double>(near) / ps.size();
}

double uniform_border_fraction(const Domain& d) {
  const double b = border_band(d), w = d.width(), h = d.height();
  if (!(w > 0 && h > 0)) return std::nan("");
  // The inner rectangle (W - 2b) x (H - 2b) holds the points that are not near the border.
  return 1.0 - (w - 2 * b) * (h - 2 * b) / (w * h);
}

}  // namespace ppsynth
