#pragma once
// Points parked on the border: the Gabor method's known artifact (its maps are not periodic,
// the positions wrap), so evaluate() reports the share of points in a band along the border.
//
// The band is 1 % of the domain's SHORTER side, the same width on all four edges: on the
// paper's unit square that is the band of every earlier result (1 % of the side); on a 4 x 1
// strip a band of 1 % of each side's own length would be 4 times wider along the short edges
// than along the long ones, and the share would weigh the ends of the strip 4 times more.
// What uniform points put in the band depends on the shape (the band covers
// 1 - (W - 2b)(H - 2b) / (W H) of the area: 3.96 % of a square, 2.49 % of a 4 x 1 strip), so
// it is reported beside the measured share (uniform_border_fraction).
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

// Band width b (domain units) of `d`: kBorderBand x its shorter side.
inline constexpr double kBorderBand = 0.01;
double border_band(const Domain& d);

// Share of the points of `ps` within border_band of its domain's border; NaN when empty.
double border_fraction(const PointSet& ps);

// The share that uniform points on `d` put in that band: its area over the domain's area.
double uniform_border_fraction(const Domain& d);

// The border's density at several band widths, each over what uniform points put there
// (1 = uniform). border_fraction is one band; a profile tells the two artifacts apart that it
// mixes: the published method's pile (points parked within a fraction of a spacing of the
// edge: > 1 in the narrowest bands) and a thin seam behind it or left by a relax that moved
// the pile away (< 1); one output can show both at once (docs/lab/large_outputs.md,
// "Numbers that were in code comments").
// Widths as fractions of the domain's shorter side, as kBorderBand.
inline constexpr double kBorderProfileBands[] = {0.005, 0.01, 0.02, 0.04};
struct BorderProfile {
  std::vector<double> band;          // fraction of the shorter side
  std::vector<double> share;         // of the points within that width of the border
  std::vector<double> over_uniform;  // share / uniform's share; NaN for an empty set
};
BorderProfile border_profile(const PointSet& ps);

}  // namespace ppsynth
