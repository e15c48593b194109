#pragma once
// The verdict: "is this output a plausible realization of the exemplar's process?", as a
// two-sample test with a p-value for all points, per class and per class pair.
//
// Test: Hahn's (2012) studentized permutation test of equal K-functions, with sub-windows as
// the replicates. Chosen over the alternatives because it needs no model of the process (a
// parametric bootstrap needs one fitted to every exemplar, and tests that model rather than
// the exemplar) and no simulations from it (a global envelope test needs them); it uses the
// two patterns alone, and its studentization keeps it valid when the groups' variances differ.
//
//   1. Both patterns in exemplar units: the output's coordinates divided by the zoom (output
//      units per exemplar unit; given, or from the densities, crops.hpp); then both in units of
//      the sub-window's shorter side, so that the test is the same at any coordinate scale.
//      The output's classes are matched to the exemplar's by label (class_match.hpp).
//   2. Units: the exemplar's window cut into split x split cells; the output cut into cells of
//      that size from its corner, of which a block of at most kOutputBlockPerExemplarSide x
//      split cells a side takes part (placed by the seed): the test of a larger output is the
//      test of the default output's size, at a place in it. Each cell is shrunk by guard / 2
//      of its side on every side (guard = the share of a cell's side left between two
//      sub-windows), so that neighboring sub-windows share less of a cluster or of a hard
//      core's reach.
//   3. Per sub-window, K with the translation correction (second_order.hpp) on r_values
//      radii in (0, r_max]; "all" takes every point, "class k" its points, "pair (i, j)" K_ij
//      of i to j (symmetric under translation). A sub-window with fewer than 2 points of the
//      class (1 of each type for a pair) has no K and is left out of that row, in both groups
//      alike. r_max per row: a quarter of the sub-window's shorter side (spatstat's rule),
//      extended by sixteenths up to half of it until at least half of the exemplar's
//      sub-windows hold a pair of the row within it (any one will do at half): a pattern whose
//      closest pairs lie beyond a quarter would otherwise have K = 0 at every radius, and any
//      output without close pairs would match it.
//   4. T = sum_r (mean_1(r) - mean_2(r))^2 / (var_1(r) / n_1 + var_2(r) / n_2) * dr over the
//      radii where the denominator is above the rounding noise of its sums (relative, so the
//      same at any scale): Hahn's statistic, K-bar the plain means.
//   5. p = (1 + #{T* >= T}) / (1 + permutations), T* over random reassignments of the
//      sub-windows to groups of the same sizes (seeded: the same p for the same inputs).
// Each row is "pass" (p >= alpha), "fail" (p < alpha, or a class one pattern has and the other
// lacks: missing from the output or extra in it) or "cannot judge" with the reason (fewer than
// 2 sub-windows in a group; too few distinct reassignments for p to fall below alpha; no pair
// of the row within half a sub-window's side in the exemplar; no radius with evidence).
// "passed" is true when every row passes, false when any fails, null when none fails but some
// cannot judge: "cannot judge" is never a pass. Permutation counts whose smallest p,
// 1 / (1 + permutations), is not below alpha are refused.
// The calibration (independent realizations pass at the nominal rate) and the power of
// these defaults are measured in docs/lab/verdict/README.md.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

// The output's block of sub-windows is at most this many exemplar windows a side: the default
// output's (2 x 2 copies), where the test's calibration is measured. Over more output
// sub-windows than that, against the exemplar's few, a reassignment often leaves the small
// group with alike sub-windows and a tiny variance, Hahn's T of such reassignments swamps
// the observed one, and the power against a clustered exemplar falls as the output grows;
// sub-windows scattered over a larger output instead make the test reject a clustered
// process's own realizations too often (docs/lab/verdict/README.md, "Power against the
// output's size").
inline constexpr int kOutputBlockPerExemplarSide = 2;

struct VerdictOptions {
  int split = 2;            // the exemplar in split x split sub-windows
  double guard = 0.1;       // share of a cell's side left out between sub-windows, [0, 0.9]
  int permutations = 1999;  // random reassignments
  uint64_t seed = 1;
  int r_values = 64;        // radii in (0, r_max]
  double alpha = 0.05;      // "pass" means p >= alpha
  double zoom = 0;          // output units per exemplar unit; 0: from the densities
};

// InputError naming the eval flag for options no test can use (a permutation count that
// cannot reach alpha among them).
void check_verdict_options(const VerdictOptions& opt);

// { "test", "statistic", "split", "guard", "zoom", "sub_window": [w, h] (exemplar units),
//   "r_max" (spatstat's quarter, exemplar units), "r_rule", "permutations", "seed", "alpha",
//   "classes": class_match_json, "failed", "cannot_judge", "passed": true | false | null,
//   "rows": [ { "row": "all" | "class" | "pair", "class" + "label" / "ci", "cj" + "labels",
//               "outcome": "pass" | "fail" | "cannot judge", "p" (null unless tested),
//               "pass" (true, false, or null when it cannot judge), "statistic",
//               "units": [exemplar, output], "r_max" (exemplar units) and "r_max_sides" (in
//               sub-window sides) when tested, "reason" (when decided without a p) } ] }
nlohmann::json verdict(const PointSet& exemplar, const PointSet& output, const VerdictOptions& opt = {});

// Lines for eval's table: one per row, "  all classes   p = 0.4120  pass  (4 + 16 sub-windows)",
// then the whole verdict and any class that does not match.
std::string format_verdict(const nlohmann::json& v);
// "all classes", "class 1000", "pair 1000-1001" (labels).
std::string verdict_row_name(const nlohmann::json& row);

}  // namespace ppsynth
