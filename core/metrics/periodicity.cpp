#include "core/metrics/periodicity.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/metrics/periodogram.hpp"
#include "core/metrics/summary_stats.hpp"

namespace ppsynth {

namespace {

using nlohmann::json;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// A tiled copy on a whole number of periods has ~0 (rounding) between the harmonics: the
// denominator is at least this fraction of the grid's mean power, as spectrum_peak's ring
// median (periodogram.hpp), so the ratio stays a readable number.
constexpr double kBetweenFloor = 1e-3;

}  // namespace

void check_periodicity_options(const PeriodicityOptions& opt) {
  if (opt.harmonics < 1 || opt.harmonics > 64)
    throw InputError("periodicity harmonics (--periodicity-harmonics) must be in 1..64 (got " +
                     std::to_string(opt.harmonics) + ")");
  if (!(opt.periodic_ratio > 1) || !std::isfinite(opt.periodic_ratio))
    throw InputError("periodicity threshold (--periodic-ratio) must be a number > 1");
}

PeriodicityRatio periodicity_ratio(const PointSet& ps, Vec2 period, int harmonics) {
  if (!(period.x > 0 && period.y > 0) || !std::isfinite(period.x) || !std::isfinite(period.y))
    throw InputError("periodicity: the period must have a positive, finite width and height");
  const Domain& d = ps.domain();
  // In period units the harmonics are the whole frequencies; a grid of half steps puts one
  // frequency between each two harmonics.
  const PointSet scaled = ps.mapped_to(Domain{d.x0 / period.x, d.y0 / period.y, d.x1 / period.x, d.y1 / period.y});
  PeriodogramOptions po;
  po.frequencies = 2 * harmonics + 1;
  po.step = 0.5;
  const Periodogram p = periodogram(scaled, po);
  std::vector<double> on, between;
  double sum = 0;
  size_t count = 0;
  for (int ky = 0; ky <= p.F; ++ky)
    for (int kx = -p.F; kx <= p.F; ++kx) {
      if (ky == 0 && kx <= 0) continue;  // the half plane: P(-f) = P(f), and no DC
      const double v = p.at(kx, ky);
      sum += v, ++count;
      (kx % 2 == 0 && ky % 2 == 0 ? on : between).push_back(v);
    }
  PeriodicityRatio r;
  r.harmonics = on.size();
  r.between = between.size();
  r.harmonic_median = quantile(on, 0.5);
  r.between_median = quantile(between, 0.5);
  const double floor = std::max(kBetweenFloor * sum / static_cast<double>(count), 1e-300);
  r.ratio = r.harmonic_median / std::max(r.between_median, floor);
  return r;
}

json periodicity_report(const PointSet& exemplar, const PointSet& output, double zoom, const PeriodicityOptions& opt) {
  check_periodicity_options(opt);
  if (!(zoom > 0) || !std::isfinite(zoom)) throw InputError("periodicity: the zoom must be a number > 0");
  const Vec2 period{exemplar.domain().width() * zoom, exemplar.domain().height() * zoom};
  const Domain& d = output.domain();
  const double px = d.width() / period.x, py = d.height() / period.y;
  json j = {{"measures",
             "the output's periodogram at the exemplar's period and its harmonics (m / width, n / height in output "
             "units, |m|, |n| <= harmonics), its median over the median between them (about 1: no repeat; a tiled copy: "
             "far above); flagged periodic from periodic_ratio"},
            {"harmonics", opt.harmonics},
            {"period", {period.x, period.y}},
            {"periods", {px, py}},
            {"periodic_ratio", opt.periodic_ratio}};
  if (output.size() < 2) {
    j["ratio"] = j["harmonic_median"] = j["between_median"] = j["periodic"] = nullptr;
    return j;
  }
  const PeriodicityRatio r = periodicity_ratio(output, period, opt.harmonics);
  j["ratio"] = num(r.ratio);
  j["harmonic_median"] = num(r.harmonic_median);
  j["between_median"] = num(r.between_median);
  j["periodic"] = std::isfinite(r.ratio) ? json(r.ratio >= opt.periodic_ratio) : json(nullptr);
  return j;
}

}  // namespace ppsynth
