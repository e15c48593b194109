#include "core/metrics/quadrant.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace ppsynth {

std::vector<Domain> quadrant_windows(const Domain& d) {
  const double xm = 0.5 * (d.x0 + d.x1), ym = 0.5 * (d.y0 + d.y1);
  return {{d.x0, d.y0, xm, ym}, {xm, d.y0, d.x1, ym}, {d.x0, ym, xm, d.y1}, {xm, ym, d.x1, d.y1}};
}

std::vector<PointSet> quadrant_patches(const PointSet& ps) { return cut_patches(ps, quadrant_windows(ps.domain())); }

PatchMetrics quadrant_metrics(const PointSet& exemplar, const PointSet& output, const PcfOptions& opt,
                              Curve* exemplar_pcf, Curve* output_pcf, size_t wasserstein_max_pairs) {
  if (exemplar.empty()) throw InputError("quadrant_metrics: empty exemplar");
  return patch_metrics(exemplar, quadrant_patches(output), opt, exemplar_pcf, output_pcf, wasserstein_max_pairs);
}

QuadrantSplit split_quadrants(const PointSet& exemplar, const PointSet& output, int classes) {
  return split_patches(exemplar, quadrant_patches(output), classes);
}

double quadrant_cross_pcf_mse(const QuadrantSplit& split, int ci, int cj, const PcfOptions& opt,
                              Curve* exemplar_pcf, Curve* output_pcf) {
  return patch_cross_pcf_mse(split, ci, cj, opt, exemplar_pcf, output_pcf);
}

double quadrant_cross_pcf_mse(const PointSet& exemplar, const PointSet& output, int ci, int cj,
                              const PcfOptions& opt, Curve* exemplar_pcf, Curve* output_pcf) {
  const int K = std::max({exemplar.num_classes(), output.num_classes(), ci + 1, cj + 1});
  return quadrant_cross_pcf_mse(split_quadrants(exemplar, output, K), ci, cj, opt, exemplar_pcf, output_pcf);
}

}  // namespace ppsynth
