#pragma once
// Patches -> metrics: the one comparison every evaluation protocol ends in. A protocol
// (quadrant.hpp: the paper's 4 quadrants; crops.hpp: N random exemplar-sized crops) only
// chooses windows on the output; each window is cut out and mapped onto the unit square
// (cut_patches), and every patch is compared with the exemplar (mapped onto the unit square
// too) the same way:
//   pcf_mse     : curve_mse(pcf(exemplar), pcf(patch)) (pcf.hpp)
//   wasserstein : wasserstein_distance(exemplar, patch)  (unit-square units)
//   chamfer     : chamfer_distance(exemplar, patch)      (unit-square units)
// and the results averaged over the patches (the per-patch values are kept too).
// PCF radii: both curves use the same r_max, from the exemplar's count in the unit square
// (unless opt.r_max > 0), and the rectangle estimator unless opt.periodic.
// An empty patch makes its Wasserstein/Chamfer undefined: it is skipped for those two
// (PCF of an empty patch = 0; its per-patch Wasserstein/Chamfer are NaN) and the average
// taken over the others; all patches empty => NaN.
// Wasserstein beyond the exact limit (wasserstein.hpp: |exemplar| x |patch| above
// `wasserstein_max_pairs` in any patch): `wasserstein` is NaN, `wasserstein_exact` false and
// `wasserstein_estimate` the mean of the patches' subsample estimates (per patch: the
// estimates), with the largest sample sizes used. Otherwise wasserstein_estimate == wasserstein.
// Cost: O(N log N) for Chamfer and the PCF's radius searches (pcf.hpp), the exact assignment
// O(n^2 m) up to the limit, per patch.
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
  // One value per patch, in patch order (what the means above average).
  std::vector<double> patch_pcf_mse, patch_wasserstein, patch_chamfer;
};

// `ps` mapped onto the unit square (a set already there keeps its positions; the periodic flag
// is dropped so that patches and exemplar use the same PCF estimator).
PointSet to_unit_square(const PointSet& ps);

// Each window of `ps` (PointSet::crop_to_unit: half-open, closed on the domain's far edges)
// mapped onto the unit square.
std::vector<PointSet> cut_patches(const PointSet& ps, const std::vector<Domain>& windows);

// The exemplar against each patch (already on the unit square). `exemplar_pcf` /
// `output_pcf` (optional) receive the exemplar's curve and the mean of the patches' curves.
// InputError for an empty exemplar or no patches.
PatchMetrics patch_metrics(const PointSet& exemplar, const std::vector<PointSet>& patches,
                           const PcfOptions& opt = {}, Curve* exemplar_pcf = nullptr,
                           Curve* output_pcf = nullptr,
                           size_t wasserstein_max_pairs = kWassersteinExactPairs);

// The exemplar (on the unit square) and the patches, each divided by class 0..classes-1
// once, for many class pairs (O(N) once instead of O(N) per pair: 465 pairs of 30 classes)
// and for the per-class rows.
struct PatchSplit {
  std::vector<PointSet> exemplar_class;            // [class]
  std::vector<std::vector<PointSet>> patch_class;  // [patch][class]
};
PatchSplit split_patches(const PointSet& exemplar, const std::vector<PointSet>& patches, int classes);

// Points of each class 0..classes-1 of `ps`, in their order (one pass).
std::vector<PointSet> split_classes(const PointSet& ps, int classes);

// Cross-class PCF MSE between classes ci and cj: cross_pcf of the exemplar against each
// patch's (r_max from the exemplar's N_ci + N_cj), averaged; `per_patch` (optional) gets
// each patch's MSE.
double patch_cross_pcf_mse(const PatchSplit& split, int ci, int cj, const PcfOptions& opt = {},
                           Curve* exemplar_pcf = nullptr, Curve* output_pcf = nullptr,
                           std::vector<double>* per_patch = nullptr);

}  // namespace ppsynth
