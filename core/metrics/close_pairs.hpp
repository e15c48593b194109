#pragma once
// Close pairs: the output's smallest distances against the exemplar's, per row (all points,
// each class, each class pair), in the plane (neither pattern is taken as periodic: a tiled
// copy's seams are the output's own pairs).
//
//   "exemplar_min": the exemplar's closest pair of the row (exemplar units);
//   "pairs_below": the output's pairs of the row closer than that (the output in exemplar
//     units: its coordinates over the zoom), and "share_below": the share of the row's output
//     points in such a pair (for a pair i-j, of the points of classes i and j);
//   "exemplar_normalized", "output_normalized": the closest pair over the largest possible
//     for the row's density, d_max = 2 packing_radius(n, area) (nearest_neighbor.hpp:
//     sqrt(2 / (sqrt(3) n)) on the unit square; n the row's points, n_i + n_j for a pair):
//     the normalized minimum distance of the paper's Table 1 (its relative radius, measured
//     in the plane here where evaluate()'s "relative_radius" takes the torus).
// A row whose exemplar holds no pair (fewer than 2 points; an empty class of a pair) has no
// threshold: its "exemplar_min", "pairs_below" and "share_below" are null. Rows of pairs up to
// kMaxPairClasses classes (overlap.hpp), as the other rows.
// Cost: k-d tree queries, O(N log N) plus the pairs found below the threshold.
#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

// `output`'s classes matched to the exemplar's (class_match.hpp); `zoom` output units per
// exemplar unit. { "measures", "rows": [ { "row": "all" | "class" | "pair", "class" | "ci",
// "cj", the fields above } ] }
nlohmann::json close_pairs_report(const PointSet& exemplar, const PointSet& output, double zoom);

}  // namespace ppsynth
