#include "core/metrics/quadrant.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/metrics/chamfer.hpp"
#include "core/metrics/wasserstein.hpp"

namespace ppsynth {

namespace {

PointSet to_unit(const PointSet& ps) {
  const Domain& d = ps.domain();
  if (d.x0 == 0 && d.y0 == 0 && d.x1 == 1 && d.y1 == 1) {
    PointSet out = ps;
    Domain u;
    out.set_domain(u);  // drop a periodic flag: patches and exemplar use the same estimator
    return out;
  }
  return ps.mapped_to(Domain{});
}

}  // namespace

std::vector<PointSet> quadrant_patches(const PointSet& ps) {
  const Domain& d = ps.domain();
  const double xm = 0.5 * (d.x0 + d.x1), ym = 0.5 * (d.y0 + d.y1);
  const Domain w[4] = {{d.x0, d.y0, xm, ym}, {xm, d.y0, d.x1, ym}, {d.x0, ym, xm, d.y1}, {xm, ym, d.x1, d.y1}};
  std::vector<PointSet> out;
  for (const Domain& q : w) out.push_back(ps.crop_to_unit(q));
  return out;
}

PatchMetrics quadrant_metrics(const PointSet& exemplar, const PointSet& output, const PcfOptions& opt,
                              Curve* exemplar_pcf, Curve* output_pcf) {
  if (exemplar.empty()) throw InputError("quadrant_metrics: empty exemplar");
  const PointSet ex = to_unit(exemplar);
  PcfOptions o = opt;
  if (o.r_max <= 0) o.r_max = pcf_unit(ex.size(), 1.0);
  const Curve ex_curve = pcf(ex, o);
  std::vector<Curve> curves;
  PatchMetrics m;
  int matched = 0;
  for (const PointSet& patch : quadrant_patches(output)) {
    curves.push_back(pcf(patch, o));
    m.pcf_mse += curve_mse(ex_curve, curves.back());
    if (patch.empty()) continue;
    m.wasserstein += wasserstein_distance(ex, patch);
    m.chamfer += chamfer_distance(ex, patch);
    ++matched;
  }
  m.pcf_mse /= 4;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.wasserstein = matched ? m.wasserstein / matched : nan;
  m.chamfer = matched ? m.chamfer / matched : nan;
  if (exemplar_pcf) *exemplar_pcf = ex_curve;
  if (output_pcf) *output_pcf = mean_curve(curves);
  return m;
}

double quadrant_cross_pcf_mse(const PointSet& exemplar, const PointSet& output, int ci, int cj,
                              const PcfOptions& opt, Curve* exemplar_pcf, Curve* output_pcf) {
  const PointSet ex = to_unit(exemplar);
  const PointSet ea = ex.subset_class(ci), eb = ex.subset_class(cj);
  PcfOptions o = opt;
  if (o.r_max <= 0) o.r_max = pcf_unit(ea.size() + eb.size(), 1.0);
  const Curve ex_curve = cross_pcf(ea, eb, o);
  std::vector<Curve> curves;
  double mse = 0;
  for (const PointSet& patch : quadrant_patches(output)) {
    curves.push_back(cross_pcf(patch.subset_class(ci), patch.subset_class(cj), o));
    mse += curve_mse(ex_curve, curves.back());
  }
  if (exemplar_pcf) *exemplar_pcf = ex_curve;
  if (output_pcf) *output_pcf = mean_curve(curves);
  return mse / 4;
}

}  // namespace ppsynth
