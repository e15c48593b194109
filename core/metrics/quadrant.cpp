#include "core/metrics/quadrant.hpp"

#include <algorithm>
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
                              Curve* exemplar_pcf, Curve* output_pcf, size_t wasserstein_max_pairs) {
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
    const WassersteinResult w = wasserstein_estimate(ex, patch, wasserstein_max_pairs);
    m.wasserstein += w.value;
    m.wasserstein_exact = m.wasserstein_exact && w.exact;
    m.wasserstein_sample_a = std::max(m.wasserstein_sample_a, w.sample_a);
    m.wasserstein_sample_b = std::max(m.wasserstein_sample_b, w.sample_b);
    m.chamfer += chamfer_distance(ex, patch);
    ++matched;
  }
  m.pcf_mse /= 4;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.wasserstein = matched ? m.wasserstein / matched : nan;
  m.wasserstein_estimate = m.wasserstein;
  if (!m.wasserstein_exact) m.wasserstein = nan;
  m.chamfer = matched ? m.chamfer / matched : nan;
  if (exemplar_pcf) *exemplar_pcf = ex_curve;
  if (output_pcf) *output_pcf = mean_curve(curves);
  return m;
}

namespace {

// Points of each class 0..classes-1, in their order (one pass).
std::vector<PointSet> by_class(const PointSet& ps, int classes) {
  std::vector<std::vector<size_t>> idx(std::max(classes, 0));
  for (size_t i = 0; i < ps.size(); ++i)
    if (ps.cls(i) >= 0 && ps.cls(i) < classes) idx[ps.cls(i)].push_back(i);
  std::vector<PointSet> out;
  out.reserve(idx.size());
  for (const auto& v : idx) out.push_back(ps.subset(v));
  return out;
}

}  // namespace

QuadrantSplit split_quadrants(const PointSet& exemplar, const PointSet& output, int classes) {
  QuadrantSplit s;
  s.exemplar_class = by_class(to_unit(exemplar), classes);
  const auto patches = quadrant_patches(output);
  for (size_t q = 0; q < 4; ++q) s.patch_class[q] = by_class(patches[q], classes);
  return s;
}

double quadrant_cross_pcf_mse(const QuadrantSplit& split, int ci, int cj, const PcfOptions& opt,
                              Curve* exemplar_pcf, Curve* output_pcf) {
  const int K = static_cast<int>(split.exemplar_class.size());
  if (ci < 0 || cj < 0 || ci >= K || cj >= K)
    throw InputError("quadrant_cross_pcf_mse: class " + std::to_string(std::max(ci, cj)) + " out of range (" +
                     std::to_string(K) + " classes)");
  const PointSet& ea = split.exemplar_class[ci];
  const PointSet& eb = split.exemplar_class[cj];
  PcfOptions o = opt;
  if (o.r_max <= 0) o.r_max = pcf_unit(ea.size() + eb.size(), 1.0);
  const Curve ex_curve = cross_pcf(ea, eb, o);
  std::vector<Curve> curves;
  double mse = 0;
  for (const auto& patch : split.patch_class) {
    curves.push_back(cross_pcf(patch[ci], patch[cj], o));
    mse += curve_mse(ex_curve, curves.back());
  }
  if (exemplar_pcf) *exemplar_pcf = ex_curve;
  if (output_pcf) *output_pcf = mean_curve(curves);
  return mse / 4;
}

double quadrant_cross_pcf_mse(const PointSet& exemplar, const PointSet& output, int ci, int cj,
                              const PcfOptions& opt, Curve* exemplar_pcf, Curve* output_pcf) {
  const int K = std::max({exemplar.num_classes(), output.num_classes(), ci + 1, cj + 1});
  return quadrant_cross_pcf_mse(split_quadrants(exemplar, output, K), ci, cj, opt, exemplar_pcf, output_pcf);
}

}  // namespace ppsynth
