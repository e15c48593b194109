#pragma once
// The evaluation suite in one call: what `ppsynth eval` prints and reports consume.
// evaluate(exemplar, output) returns JSON:
//   "exemplar", "output": { "count", "class_counts", "d_min", "d_min_square", "mean_nn",
//                           "border_fraction", "border_fraction_uniform",
//                           "relative_radius", "relative_radius_per_class" }   (d_min/mean_nn
//                           toroidal, d_min_square in the plain square, domain units;
//                           relative radius per nearest_neighbor.hpp; "border_fraction":
//                           share of points within 1 % of the domain's shorter side of the
//                           border, "border_fraction_uniform" what uniform points on that
//                           domain put there: 3.96 % on a square, 2.49 % on a 4 x 1 strip;
//                           parked points raise the first above the second; border.hpp)
//                           "border_profile": { "band": [0.005, 0.01, 0.02, 0.04] (of the
//                           shorter side), "over_uniform": [...] } the density within each
//                           width of the border over uniform points' (1 = uniform; a pile
//                           > 1, a thin seam < 1; border.hpp)
//   "upscale": sqrt(output count / exemplar count) (the per-axis u of method.md; ~2)
//   "protocol": which patches of the output were compared with the exemplar
//              (eval_protocol.hpp): { "name": "quadrants" | "crops", "requested": "auto" |
//              "quadrants" | "crops", "reason", "patches" (4 or the crop count),
//              "crop_size": [w, h] (a quadrant's or a crop's size, output units), "zoom"
//              (output units per exemplar unit, from the densities) } and for crops "seed"
//              and "windows": [[x0, y0, x1, y1], ...] (output coordinates)
//   "all":     patch metrics of all classes together { "pcf_mse", "wasserstein",
//              "chamfer", "exemplar_points", "pcf": { "r", "exemplar", "output" } }
//              (patches.hpp: each the mean over the patches; exemplar_points: how many
//              points the row's curve rests on). With crops every row also carries
//                "per_crop": { "pcf_mse": [...], "wasserstein": [...], "chamfer": [...] }
//                  (one value per crop, in "windows" order; null for an empty crop's
//                  Wasserstein/Chamfer; Wasserstein values are the subsample estimates
//                  when "wasserstein_method" is "subsample")
//                "pcf_mse_quartiles", "wasserstein_quartiles", "chamfer_quartiles":
//                  [first quartile, median, third quartile] over the crops (linear
//                  interpolation, summary_stats.hpp; nulls left out)
//   "classes_matched": how the output's classes were matched to the exemplar's: by label
//              (class_match.hpp), with the labels "missing" from the output and "extra" in it
//              (their verdict rows fail). Every row below uses the matched ids: "class" k is
//              the exemplar's class k and the output's class of its label.
//   "classes": [ { "class", "label", same metrics } ]  per class (present in the exemplar)
//   "cross":   [ { "ci", "cj", "pcf_mse", "pcf": {...} } ] for every class pair ci < cj
//              (crops: with "per_crop": { "pcf_mse" } and "pcf_mse_quartiles")
//   "overlap": [ { "ci", "cj", "pairs", "pair_fraction", "point_fraction" } ] (when both
//              sets have a "radius" attribute; output and exemplar as "output"/"exemplar")
//   "spectrum": { "frequency", "exemplar", "output" } radially averaged power (optional),
//              with "peak_ratio": { "exemplar", "output" } (periodogram.hpp: the strongest
//              frequency over the median of its ring; tiled copies and lattices score high)
//   "second_order": the field's K, L, g per row and the mark correlations, exemplar and
//              output in exemplar units (second_order_report.hpp; unless second_order is false)
//   "verdict": the two-sample test per row, "is the output a plausible realization of the
//              exemplar's process?" (verdict.hpp; unless verdict is false)
//   "scorecard": { "novelty": is the output a translated copy of the exemplar (novelty.hpp),
//              "fidelity": per row its L and g distances in spreads of independent
//              realizations, within the band or not (fidelity.hpp; each row with the
//              verdict's "verdict_p" and "verdict_outcome" beside it when the verdict ran),
//              "periodicity": does it repeat with the exemplar's period (periodicity.hpp),
//              "close_pairs": its closest pairs against the exemplar's (close_pairs.hpp),
//              "border": { "measures", "band", "exemplar", "output" } the border profiles
//              above, over uniform's }
//              (unless scorecard is false; docs/explanation/scorecard.md)
//   "options": the PCF options used (and wasserstein_exact_pairs).
// Wasserstein per row: "wasserstein_method" "exact" | "subsample". Beyond the exact limit
// (EvalOptions::wasserstein_max_pairs, |exemplar| x |patch| per patch; wasserstein.hpp)
// "wasserstein" is null and the row carries "wasserstein_estimate" (subsample estimate) and
// "wasserstein_sample" [exemplar points, patch points]; "wasserstein_note" says it in words and
// the table prints the estimate as "~value" with a note.
// More than kMaxPairClasses (64) classes: "cross" is empty and "cross_skipped" says why.
// Cost (measured in docs/lab/performance/README.md, "Evaluation on large inputs"): O(N log N) for the
// nearest-neighbor statistics, Chamfer and the PCFs (k-d tree queries), the exact
// Wasserstein O(n^2 m) up to the limit, per patch (crops: `crops` patches instead of 4).
// Inputs of 50,000 points or more log each stage.
// PCF curves are included unless options.include_curves is false ("r" in r_max units,
// "output" = mean of the patches' curves).
#include <string>

#include <nlohmann/json.hpp>

#include "core/metrics/eval_protocol.hpp"
#include "core/metrics/fidelity.hpp"
#include "core/metrics/novelty.hpp"
#include "core/metrics/pcf.hpp"
#include "core/metrics/periodicity.hpp"
#include "core/metrics/verdict.hpp"
#include "core/metrics/wasserstein.hpp"
#include "core/point_set.hpp"

namespace ppsynth {

struct EvalOptions {
  PcfOptions pcf;
  bool include_curves = true;
  bool spectrum = false;      // radially averaged spectra of both sets (O(N F^2))
  int spectrum_frequency = 32;
  bool periodic_overlap = false;
  size_t wasserstein_max_pairs = kWassersteinExactPairs;  // exact assignment up to this many pairs
  PatchProtocol protocol = PatchProtocol::Auto;  // eval_protocol.hpp
  int crops = kDefaultCrops;                     // crops protocol: how many crops
  uint64_t crop_seed = kDefaultCropSeed;         // crops protocol: where they go
  double zoom = 0;  // crops protocol, second order, verdict: output units per exemplar unit; 0: from the densities (eval's, a run's)
  bool second_order = true;  // K, L, g, mark correlation (second_order_report.hpp)
  bool verdict = true;       // the two-sample test (verdict.hpp); its zoom is `zoom`'s
  VerdictOptions verdict_options;
  bool scorecard = true;  // novelty, fidelity, periodicity, close pairs, border (novelty.hpp, fidelity.hpp, periodicity.hpp, close_pairs.hpp), at `zoom`'s scale
  NoveltyOptions novelty;
  FidelityOptions fidelity;
  PeriodicityOptions periodicity;
};

// Refuses options no evaluation can use (InputError naming the option and the command's
// flag): bins outside 2..10000, r_max outside [0, 1] (radii reach 2.5 r_max: beyond 1 every
// pair is within reach and the PCF turns quadratic; NaN too), an exact-Wasserstein limit
// outside 1..4e8 pairs (a 3.2 GB cost matrix), a crop count outside 1..10000, a protocol
// that is not one of the enum's, a spectrum frequency outside 1..1024, novelty, fidelity and
// periodicity options outside novelty.hpp's, fidelity.hpp's and periodicity.hpp's ranges. evaluate() calls it first.
void check_eval_options(const EvalOptions& opt);

nlohmann::json evaluate(const PointSet& exemplar, const PointSet& output,
                        const EvalOptions& opt = {});

// evaluate()'s result as a table for people: core/metrics/evaluation_text.hpp.

}  // namespace ppsynth
