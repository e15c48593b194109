#pragma once
// Fidelity, calibrated: is the output's second-order structure as close to the exemplar's as an
// independent realization of the exemplar's process would be, at the output's size?
//
// Per row (all points, each class, each class pair up to kMaxFidelityPairClasses classes, the
// mark correlation of every attribute both sets carry), both patterns in exemplar units (the
// output's coordinates over the zoom), on one r grid of r_values radii up to r_max = the
// sub-windows' quarter side (spatstat's rule on the windows the spread comes from), capped at
// kFidelityMaxSpacings mean spacings of the row:
//   "l": sup_r |L_out - L_ex| in the row's mean spacings 1 / sqrt(lambda) (lambda: the
//        exemplar's intensity of the row's second class, as spatstat's cross functions);
//   "g": the root mean square of g_out - g_ex over the radii from the kernel's half-width h up
//        (below h the kernel estimate of g ~ 1/r is its own noise);
//   "kmm" (mark rows): sup_r |k_mm,out - k_mm,ex|.
// Each distance is divided by the spread independent realizations show at these sizes
// (subwindow_spread.hpp: the exemplar's `windows` random sub-windows of `side` times its
// sides, each against the whole exemplar, scaled to the output's area by the variance law):
//   "spreads": distance / spread (about 1 for an independent realization; "2.1 spreads");
//   "band": the band's edge in spreads, `band` times the row's "clustering" to the power
//           kFidelityClusterExponent ("clustering": 1 + the extra neighbours a point of the
//           row has within r_max over Poisson's, lambda (K_ex(r_max) - pi r_max^2), at least 1).
//           `band` is measured: the 95th percentile of independent realizations' spreads over
//           the clustering factor, six simulated processes pooled (docs/lab/scorecard/README.md;
//           each exemplar's own sub-windows put their 95th percentile too low, as they share
//           its noise and overlap);
//   "within": spreads <= band: as close as independent realizations are, at the nominal
//             false-alarm rate kFidelityNominalRate per distance.
// A row cannot judge (within null, "reason") when fewer than kMinFidelityDraws sub-windows
// hold the row's points (2 of a class, 1 of each class of a pair); it is out of band (within
// false, "reason") when the exemplar has the row's points and the output has not.
// "within" of the whole: false when any distance is out of band, null when none is and some
// cannot judge, else true. The measured false-alarm rates: docs/explanation/scorecard.md.
// Cost: per row, the K and g of the exemplar, of the output and of `windows` sub-windows of
// `side`^2 of the exemplar's area each (second_order.hpp), on r_values radii.
#include <cstdint>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

// Class pairs have rows up to this many classes (28 pairs), each costing `windows` K and g.
inline constexpr int kMaxFidelityPairClasses = 8;
// r stops at this many of the row's mean spacings 1 / sqrt(lambda) (about 113 neighbours a
// point): structure beyond a few spacings is the density's, and the pairs, the cost, grow as
// r^2 (spatstat's cap is 17.8 spacings). An exemplar of up to about 2300 points per square of
// its shorter side reaches the quarter first: every calibrated one does.
inline constexpr double kFidelityMaxSpacings = 6;
// A row with fewer sub-windows holding its points cannot judge: a band needs draws.
inline constexpr size_t kMinFidelityDraws = 16;
// The share of independent realizations the default band leaves out, per distance, as measured.
inline constexpr double kFidelityNominalRate = 0.05;
// Why the band widens with the row's clustering: a clustered exemplar's few clusters are its
// independent units, so its spread is estimated from few of them and its own distance from its
// process has a heavy tail (the exemplars that lie far from their process are the ones whose
// sub-windows agree with each other). A constant band left out 16-24 % of a Matérn process's
// realizations (about 10 clusters) and none of a regular one's; clustering, measured on the
// exemplar's own K at r_max, is about 10 there and 1 on a regular row. The exponent is the one
// that brought each of the six simulated processes within the nominal rate's binomial interval
// while keeping the power against uniform points (1/2 brought Matérn to 2 % but let uniform
// points pass it 29 of 50 times): docs/lab/scorecard/README.md.
inline constexpr double kFidelityClusterExponent = 0.25;

struct FidelityOptions {
  int windows = 64;     // random sub-windows of the exemplar
  double side = 0.5;    // their sides, as a fraction of the exemplar's
  double band = 1.72;   // within band: up to this many spreads times clustering^(1/4) (kFidelityNominalRate at the default)
  uint64_t seed = 1;    // where the sub-windows go
  int r_values = 128;   // radii in (0, r_max]
};

// InputError naming eval's flag: windows outside 16..4096, side outside [0.2, 0.8], band
// outside [1, 100], r values outside 8..2048.
void check_fidelity_options(const FidelityOptions& opt);

// The scorecard's fidelity lines: `output` (classes matched to the exemplar's, class_match.hpp)
// against `exemplar` at `zoom` output units per exemplar unit.
// { "measures", "windows", "side", "band", "nominal_rate" (null unless band is the default), "seed", "scale" (the factor of the sub-windows'
//   distances: sqrt((1 / A_out + 1 / A_ex) / (1 / a_sub - 1 / A_ex))), "output_area",
//   "exemplar_area" (exemplar units), "rows": [ { "row": "all" | "class" | "pair" | "mark",
//   "class" + "label" | "ci", "cj" + "labels" | "attribute", "r_max", "spacing" (the row's mean
//   spacing, exemplar units: L's distance is in these), "clustering", "draws",
//   per distance ("l", "g" or "kmm"): { "distance", "spread", "spreads", "band", "within" },
//   "within", "reason" (when it cannot judge or is out of band without a distance) } ],
//   "out_of_band", "cannot_judge", "within" }
nlohmann::json fidelity_report(const PointSet& exemplar, const PointSet& output, double zoom, const FidelityOptions& opt);

}  // namespace ppsynth
