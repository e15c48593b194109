#pragma once
// The field's summaries of an exemplar and an output side by side, for `ppsynth eval`
// (evaluation.hpp, key "second_order"): K, L and g with the translation correction
// (second_order.hpp: spatstat's estimators, r grid and bandwidth), for all points, each
// class and each class pair (K_ij, L_ij, g_ij of class i to class j, i < j), and the mark
// correlation of every attribute both sets carry (mark_correlation.hpp). Both are measured in
// exemplar units: the output's coordinates divided by `zoom` (output units per exemplar unit),
// on the r grid spatstat would give the exemplar's row.
//
//   { "correction": "translation", "zoom",
//     "rows": [ { "row": "all" | "class" | "pair", "class" / "ci", "cj",
//                 "l_sup": max over r of |L_output - L_exemplar| (exemplar units),
//                 "l_sup_spacings": the same over the row's mean spacing 1 / sqrt(lambda),
//                 with curves: "r", "exemplar": { "k", "l", "g" }, "output": { ... } } ],
//     "mark_correlation": [ { "attribute", "sup": max |k_mm difference|, curves: "r",
//                             "exemplar", "output" } or { "attribute", "skipped": why } ] }
// A row with fewer than 2 points (one of each type for a pair) in either set has null values.
// More than kMaxPairClasses (64, as the cross-class PCFs) classes: no "pair" rows, and
// "pairs_skipped" says why (K (K - 1) / 2 rows of curves: 300 classes made 44,850, gigabytes).
#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

nlohmann::json second_order_report(const PointSet& exemplar, const PointSet& output, double zoom, bool curves);

}  // namespace ppsynth
