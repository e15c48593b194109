#include "core/metrics/border.hpp"

#include <algorithm>
#include <cmath>

namespace ppsynth {

namespace {

double band_width(const Domain& d, double fraction) { return fraction * std::min(d.width(), d.height()); }

double share_within(const PointSet& ps, double fraction) {
  if (ps.size() == 0) return std::nan("");
  const Domain& d = ps.domain();
  const double b = band_width(d, fraction);
  size_t near = 0;
  for (const Vec2& p : ps.positions())
    if (p.x < d.x0 + b || p.x > d.x1 - b || p.y < d.y0 + b || p.y > d.y1 - b) ++near;
  return static_cast<double>(near) / ps.size();
}

double uniform_share_within(const Domain& d, double fraction) {
  const double b = band_width(d, fraction), w = d.width(), h = d.height();
  if (!(w > 0 && h > 0)) return std::nan("");
  // The inner rectangle (W - 2b) x (H - 2b) holds the points that are not near the border.
  return 1.0 - (w - 2 * b) * (h - 2 * b) / (w * h);
}

}  // namespace

double border_band(const Domain& d) { return band_width(d, kBorderBand); }

double border_fraction(const PointSet& ps) { return share_within(ps, kBorderBand); }

double uniform_border_fraction(const Domain& d) { return uniform_share_within(d, kBorderBand); }

BorderProfile border_profile(const PointSet& ps) {
  BorderProfile p;
  for (double fraction : kBorderProfileBands) {
    const double share = share_within(ps, fraction);
    p.band.push_back(fraction);
    p.share.push_back(share);
    p.over_uniform.push_back(share / uniform_share_within(ps.domain(), fraction));
  }
  return p;
}

}  // namespace ppsynth
