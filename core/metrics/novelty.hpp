#pragma once
// Novelty: how much of an output is a translated copy of a piece of a reference pattern (the
// exemplar, taken as periodic so that a tiled copy's seams still match; or another output,
// for diversity). A copy is judged point by point, on neighbourhoods:
//
//   - an output point's neighbourhood: the offsets and classes of its k nearest neighbours,
//     in units of the exemplar's mean nearest-neighbour distance (toroidal), both sets in
//     exemplar units (the output's coordinates over the zoom);
//   - its distance to a reference point's neighbourhood (same class): every one of the k
//     offsets within d of a reference neighbour of its class, and every reference neighbour
//     as close as the k-th within d of an output neighbour (both ways: a thinned or a padded
//     piece is not a copy); the best match is the smallest d over the reference's points;
//   - an output point is a copy when its best match is within `tolerance`. Only the points
//     whose neighbourhood (k-th distance + tolerance) lies inside the output's window are
//     scored: at the window's edge a neighbourhood is cut and would match nothing.
//
// A copy scores 0 (up to rounding); independent realizations of a process almost never bring
// k neighbours within the tolerance of one of the exemplar's neighbourhoods. The default k and
// tolerance and the measured false-alarm rate are in docs/explanation/scorecard.md.
//
// Cost: O(N log N) in both sets (k-d trees): a reference point is a candidate only if it has a
// neighbour within the tolerance of the output point's nearest neighbour's offset, as close as
// its own nearest (a pair index holds those offsets), and only candidates are compared in full.
#include <cstddef>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

struct NoveltyOptions {
  int k = 8;                // neighbours per neighbourhood
  double tolerance = 0.1;   // a match: within this many exemplar mean NN distances
  double copy_share = 0.2;  // the output is flagged a copy when this share of its points match
};

// Refuses k outside 1..64, a tolerance outside (0, 1] and a copy share outside (0, 1]
// (InputError naming eval's flag).
void check_novelty_options(const NoveltyOptions& opt);

struct NeighbourhoodMatch {
  size_t points = 0;   // output points
  size_t scored = 0;   // of them, with a whole neighbourhood inside the output's window
  size_t matched = 0;  // of them, matched within the tolerance
  double closest = 0;  // the smallest best-match distance (spacings); +inf when none matched
  double share() const;  // matched / scored; NaN when none was scored
};

// `output` and `reference` in one unit, `spacing` the unit of the offsets in it (the
// exemplar's mean NN distance). `reference_periodic`: its domain is a torus (its 9 images).
NeighbourhoodMatch match_neighbourhoods(const PointSet& output, const PointSet& reference, bool reference_periodic,
                                        double spacing, const NoveltyOptions& opt);

// The scorecard's novelty line: `output` (its classes matched to the exemplar's,
// class_match.hpp) against the periodic exemplar, at `zoom` output units per exemplar unit.
// { "measures", "k", "tolerance", "unit", "spacing" (exemplar units), "points", "scored",
//   "matched", "share" (null when none scored), "closest" (null when none matched),
//   "copy_share", "copy" (share >= copy_share; null when none scored) }
nlohmann::json novelty_report(const PointSet& exemplar, const PointSet& output, double zoom, const NoveltyOptions& opt);

// Diversity: `output` against `other` (another seed's output, classes matched to the
// exemplar's), neither periodic, both at `zoom`: the same fields, "copy" saying the two are
// translates of each other over that share of the points.
nlohmann::json diversity_report(const PointSet& exemplar, const PointSet& output, const PointSet& other, double zoom,
                                const NoveltyOptions& opt);

}  // namespace ppsynth
