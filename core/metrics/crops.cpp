#include "core/metrics/crops.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "core/error.hpp"

namespace ppsynth {

namespace {

// A uniform double in [0, 1) from the top 53 bits (std::uniform_real_distribution is not
// specified bit for bit across standard libraries).
double unit_draw(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

double density_zoom(const PointSet& exemplar, const PointSet& output) {
  if (exemplar.empty() || output.empty()) throw InputError("crops: the exemplar and the output need points");
  const double a_ex = exemplar.domain().area(), a_out = output.domain().area();
  if (!(a_ex > 0) || !(a_out > 0)) throw InputError("crops: the exemplar's and the output's domains need an area");
  const double density_ex = exemplar.size() / a_ex, density_out = output.size() / a_out;
  return std::sqrt(density_ex / density_out);
}

double density_zoom_spread(const PointSet& exemplar, const PointSet& output) {
  if (exemplar.empty() || output.empty()) throw InputError("crops: the exemplar and the output need points");
  return 0.5 * std::sqrt(1.0 / static_cast<double>(exemplar.size()) + 1.0 / static_cast<double>(output.size()));
}

CropPlan plan_crops(const PointSet& exemplar, const PointSet& output, int count, uint64_t seed, double zoom) {
  if (count < 1) throw InputError("crops: the crop count must be >= 1 (got " + std::to_string(count) + ")");
  if (!(zoom >= 0) || !std::isfinite(zoom)) throw InputError("crops: the zoom must be a number > 0 (0: from the densities)");
  CropPlan p;
  p.zoom = zoom > 0 ? zoom : density_zoom(exemplar, output);
  p.width = exemplar.domain().width() * p.zoom;
  p.height = exemplar.domain().height() * p.zoom;
  const Domain& d = output.domain();
  // A crop as large as the output up to rounding fits: it is the whole domain. A zoom read from
  // the densities is an estimate, uncertain by about half the counts' relative spread: an
  // output made at the exemplar's height (a 2.56 x 1 output of a 1.6 x 1 exemplar) holds a
  // point or two fewer than its area's share and reads a crop taller than itself. Within that
  // spread the crop is the largest of the exemplar's shape that fits.
  constexpr double kFitTolerance = 1e-9;
  const double over = std::max(p.width / d.width(), p.height / d.height());
  if (zoom == 0 && over > 1 + kFitTolerance && over <= 1 + density_zoom_spread(exemplar, output)) {
    p.zoom /= over;
    p.width = exemplar.domain().width() * p.zoom;
    p.height = exemplar.domain().height() * p.zoom;
    p.zoom_fitted = true;
  }
  if (p.width > d.width() * (1 + kFitTolerance) || p.height > d.height() * (1 + kFitTolerance)) {
    std::ostringstream s;
    s << "crops: an exemplar-sized crop is " << p.width << " x " << p.height << " output units (the exemplar's "
      << exemplar.domain().width() << " x " << exemplar.domain().height() << " at zoom " << p.zoom
      << (zoom > 0 ? ", as given" : ", from the densities") << ": " << exemplar.size() << " exemplar points, " << output.size()
      << " output points) but the output domain is " << d.width() << " x " << d.height()
      << ": the output is smaller than the exemplar";
    throw InputError(s.str());
  }
  p.width = std::min(p.width, d.width());
  p.height = std::min(p.height, d.height());
  std::mt19937_64 rng(seed);
  p.windows.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double x0 = d.x0 + unit_draw(rng) * (d.width() - p.width);
    const double y0 = d.y0 + unit_draw(rng) * (d.height() - p.height);
    // The far edges never pass the domain's (so a crop ending there keeps its closed edge).
    p.windows.push_back(Domain{x0, y0, std::min(x0 + p.width, d.x1), std::min(y0 + p.height, d.y1)});
  }
  return p;
}

}  // namespace ppsynth
