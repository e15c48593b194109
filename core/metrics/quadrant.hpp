#pragma once
// The paper's four-quadrant protocol (Sec. 5.2; method.md section 6). The output (S = 4
// times the exemplar's points) is split into 4 equal quadrants of its domain
// (PointSet::crop_to_unit: half-open windows, so every point lands in exactly one), each
// rescaled to the unit square so it holds about as many points as the exemplar; each patch
// is compared with the exemplar (mapped to the unit square too) and the 4 results averaged:
//   pcf_mse     : curve_mse(pcf(exemplar), pcf(patch)) (pcf.hpp)
//   wasserstein : wasserstein_distance(exemplar, patch)  (unit-square units)
//   chamfer     : chamfer_distance(exemplar, patch)      (unit-square units)
// PCF radii: both curves use the same r_max, from the exemplar's count in the unit square
// (unless opt.r_max > 0), and the rectangle estimator unless opt.periodic.
// An empty patch makes its Wasserstein/Chamfer undefined: it is skipped for those two
// (PCF of an empty patch = 0) and the average taken over the others; all 4 empty => NaN.
// Wasserstein beyond the exact limit (wasserstein.hpp: |exemplar| x |patch| above
// `wasserstein_max_pairs` in any patch): `wasserstein` is NaN, `wasserstein_exact` false and
// `wasserstein_estimate` the mean of the patches' subsample estimates, with the largest sample
// sizes used. Otherwise wasserstein_estimate == wasserstein.
// Cost: O(N log N) for Chamfer and the PCF's radius searches (pcf.hpp), the exact assignment
// O(n^2 m) up to the limit.
#include <array>
#include <vector>

#include "core/metrics/pcf.hpp"
#include "core/metrics/wasserstein.hpp"
#include "core/point_set.hpp"

namespace ppsynth {

struct PatchMetrics {
  double pcf_mse = 0, wasserstein = 0, chamfer = 0;
  bool wasserstein_exact = true;
  double wasserstein_estimate = 0;
  size_t wasserstein_sample_a = 0, wasserstein_sample_b = 0;  // exemplar side, patch side
};

// `exemplar_pcf` / `output_pcf` (optional) receive the exemplar's curve and the mean of the
// four patches' curves.
PatchMetrics quadrant_metrics(const PointSet& exemplar, const PointSet& output,
                              const PcfOptions& opt = {}, Curve* exemplar_pcf = nullptr,
                              Curve* output_pcf = nullptr,
                              size_t wasserstein_max_pairs = kWassersteinExactPairs);

// Cross-class PCF MSE between class ci and cj under the same protocol (cross_pcf of the
// exemplar vs mean of the patches' cross_pcf; r_max from the exemplar's N_ci + N_cj).
double quadrant_cross_pcf_mse(const PointSet& exemplar, const PointSet& output, int ci, int cj,
                              const PcfOptions& opt = {}, Curve* exemplar_pcf = nullptr,
                              Curve* output_pcf = nullptr);

// The split of an exemplar and an output done once for many class pairs: the exemplar on the
// unit square and the output's 4 patches, each divided by class (O(N) once instead of O(N)
// per pair: 465 pairs of 30 classes).
struct QuadrantSplit {
  std::vector<PointSet> exemplar_class;               // [class]
  std::array<std::vector<PointSet>, 4> patch_class;   // [patch][class]
};
QuadrantSplit split_quadrants(const PointSet& exemplar, const PointSet& output, int classes);
double quadrant_cross_pcf_mse(const QuadrantSplit& split, int ci, int cj, const PcfOptions& opt = {},
                              Curve* exemplar_pcf = nullptr, Curve* output_pcf = nullptr);

// The 4 quadrant patches of `ps` (row-major: lower-left, lower-right, upper-left,
// upper-right in domain coordinates), each mapped onto the unit square.
std::vector<PointSet> quadrant_patches(const PointSet& ps);

}  // namespace ppsynth
