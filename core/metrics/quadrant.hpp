#pragma once
// The paper's four-quadrant protocol (Sec. 5.2; method.md section 6). The output (S = 4
// times the exemplar's points) is split into 4 equal quadrants of its domain
// (PointSet::crop_to_unit: half-open windows, so every point lands in exactly one), each
// rescaled to the unit square so it holds about as many points as the exemplar; each patch
// is compared with the exemplar (mapped to the unit square too) and the 4 results averaged
// (patches.hpp: pcf_mse, wasserstein, chamfer, the empty-patch and Wasserstein-estimate
// rules). It fits outputs that are squares holding about 4 times the exemplar's points;
// other outputs (rectangles in exemplar units, 10,000 points) use exemplar-sized crops
// (crops.hpp), chosen by eval_protocol.hpp.
#include <vector>

#include "core/metrics/patches.hpp"
#include "core/metrics/pcf.hpp"
#include "core/metrics/wasserstein.hpp"
#include "core/point_set.hpp"

namespace ppsynth {

// The 4 quadrants of `d` (row-major: lower-left, lower-right, upper-left, upper-right).
std::vector<Domain> quadrant_windows(const Domain& d);

// The 4 quadrant patches of `ps` (quadrant_windows order), each mapped onto the unit square.
std::vector<PointSet> quadrant_patches(const PointSet& ps);

// patch_metrics of the exemplar against the output's 4 quadrant patches.
PatchMetrics quadrant_metrics(const PointSet& exemplar, const PointSet& output,
                              const PcfOptions& opt = {}, Curve* exemplar_pcf = nullptr,
                              Curve* output_pcf = nullptr,
                              size_t wasserstein_max_pairs = kWassersteinExactPairs);

// Cross-class PCF MSE between class ci and cj under the same protocol (cross_pcf of the
// exemplar vs mean of the patches' cross_pcf; r_max from the exemplar's N_ci + N_cj).
double quadrant_cross_pcf_mse(const PointSet& exemplar, const PointSet& output, int ci, int cj,
                              const PcfOptions& opt = {}, Curve* exemplar_pcf = nullptr,
                              Curve* output_pcf = nullptr);

// The split of an exemplar and an output's 4 quadrants by class, done once for many class
// pairs (patches.hpp).
using QuadrantSplit = PatchSplit;
QuadrantSplit split_quadrants(const PointSet& exemplar, const PointSet& output, int classes);
double quadrant_cross_pcf_mse(const QuadrantSplit& split, int ci, int cj, const PcfOptions& opt = {},
                              Curve* exemplar_pcf = nullptr, Curve* output_pcf = nullptr);

}  // namespace ppsynth
