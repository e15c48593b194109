#include "core/metrics/patches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/metrics/chamfer.hpp"

namespace ppsynth {

PointSet to_unit_square(const PointSet& ps) {
  const Domain& d = ps.domain();
  if (d.x0 == 0 && d.y0 == 0 && d.x1 == 1 && d.y1 == 1) {
    PointSet out = ps;
    out.set_domain(Domain{});  // drop a periodic flag: patches and exemplar use the same estimator
    return out;
  }
  return ps.mapped_to(Domain{});
}

std::vector<PointSet> cut_patches(const PointSet& ps, const std::vector<Domain>& windows) {
  std::vector<PointSet> out;
  out.reserve(windows.size());
  for (const Domain& w : windows) out.push_back(ps.crop_to_unit(w));
  return out;
}

PatchMetrics patch_metrics(const PointSet& exemplar, const std::vector<PointSet>& patches, const PcfOptions& opt,
                           Curve* exemplar_pcf, Curve* output_pcf, size_t wasserstein_max_pairs) {
  if (exemplar.empty()) throw InputError("patch_metrics: empty exemplar");
  if (patches.empty()) throw InputError("patch_metrics: no patches to compare with the exemplar");
  const PointSet ex = to_unit_square(exemplar);
  PcfOptions o = opt;
  if (o.r_max <= 0) o.r_max = pcf_unit(ex.size(), 1.0);
  const Curve ex_curve = pcf(ex, o);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Curve> curves;
  PatchMetrics m;
  int matched = 0;
  for (const PointSet& patch : patches) {
    curves.push_back(pcf(patch, o));
    const double mse = curve_mse(ex_curve, curves.back());
    m.pcf_mse += mse;
    m.patch_pcf_mse.push_back(mse);
    if (patch.empty()) {
      m.patch_wasserstein.push_back(nan);
      m.patch_chamfer.push_back(nan);
      continue;
    }
    const WassersteinResult w = wasserstein_estimate(ex, patch, wasserstein_max_pairs);
    m.wasserstein += w.value;
    m.patch_wasserstein.push_back(w.value);
    m.wasserstein_exact = m.wasserstein_exact && w.exact;
    m.wasserstein_sample_a = std::max(m.wasserstein_sample_a, w.sample_a);
    m.wasserstein_sample_b = std::max(m.wasserstein_sample_b, w.sample_b);
    const double ch = chamfer_distance(ex, patch);
    m.chamfer += ch;
    m.patch_chamfer.push_back(ch);
    ++matched;
  }
  m.pcf_mse /= static_cast<double>(patches.size());
  m.wasserstein = matched ? m.wasserstein / matched : nan;
  m.wasserstein_estimate = m.wasserstein;
  if (!m.wasserstein_exact) m.wasserstein = nan;
  m.chamfer = matched ? m.chamfer / matched : nan;
  if (exemplar_pcf) *exemplar_pcf = ex_curve;
  if (output_pcf) *output_pcf = mean_curve(curves);
  return m;
}

std::vector<PointSet> split_classes(const PointSet& ps, int classes) {
  std::vector<std::vector<size_t>> idx(std::max(classes, 0));
  for (size_t i = 0; i < ps.size(); ++i)
    if (ps.cls(i) >= 0 && ps.cls(i) < classes) idx[ps.cls(i)].push_back(i);
  std::vector<PointSet> out;
  out.reserve(idx.size());
  for (const auto& v : idx) out.push_back(ps.subset(v));
  return out;
}

PatchSplit split_patches(const PointSet& exemplar, const std::vector<PointSet>& patches, int classes) {
  PatchSplit s;
  s.exemplar_class = split_classes(to_unit_square(exemplar), classes);
  s.patch_class.reserve(patches.size());
  for (const PointSet& p : patches) s.patch_class.push_back(split_classes(p, classes));
  return s;
}

double patch_cross_pcf_mse(const PatchSplit& split, int ci, int cj, const PcfOptions& opt, Curve* exemplar_pcf,
                           Curve* output_pcf, std::vector<double>* per_patch) {
  const int K = static_cast<int>(split.exemplar_class.size());
  if (ci < 0 || cj < 0 || ci >= K || cj >= K)
    throw InputError("cross-class PCF: class " + std::to_string(std::max(ci, cj)) + " out of range (" +
                     std::to_string(K) + " classes)");
  if (split.patch_class.empty()) throw InputError("cross-class PCF: no patches to compare with the exemplar");
  const PointSet& ea = split.exemplar_class[ci];
  const PointSet& eb = split.exemplar_class[cj];
  PcfOptions o = opt;
  if (o.r_max <= 0) o.r_max = pcf_unit(ea.size() + eb.size(), 1.0);
  const Curve ex_curve = cross_pcf(ea, eb, o);
  std::vector<Curve> curves;
  double mse = 0;
  if (per_patch) per_patch->clear();
  for (const auto& patch : split.patch_class) {
    curves.push_back(cross_pcf(patch[ci], patch[cj], o));
    const double one = curve_mse(ex_curve, curves.back());
    mse += one;
    if (per_patch) per_patch->push_back(one);
  }
  if (exemplar_pcf) *exemplar_pcf = ex_curve;
  if (output_pcf) *output_pcf = mean_curve(curves);
  return mse / static_cast<double>(split.patch_class.size());
}

}  // namespace ppsynth
