#pragma once
// How far apart two independent realizations of the exemplar's process lie, for a distance
// between summaries (an L or g curve), at the output's size: estimated from the exemplar alone.
//
// The exemplar's random sub-windows stand in for realizations. A sub-window of area a compared
// with the whole exemplar (area A) gives a distance whose noise is that of the difference of
// two estimates, one on a and one on A that contains it. Summaries of a stationary pattern
// (K, L, g) are averages over its points' neighbourhoods, so an estimate on area a has a
// variance of about s^2 / a, and the nested difference about s^2 (1 / a - 1 / A) (the whole
// shares the sub-window's own noise). An output of area A_o, independent of the exemplar, lies
// from it with a variance of about s^2 (1 / A_o + 1 / A). A distance scales as the noise's
// standard deviation, so each sub-window's distance times
//
//     sqrt(1 / A_o + 1 / A) / sqrt(1 / a - 1 / A)
//
// is a draw of the distance an independent realization of the output's size would show. Areas,
// not point counts: a clustered class's count swings from sub-window to sub-window while the
// area its noise averages over does not; for one intensity the two laws agree.
// The scaled distances' median is the "spread" (the typical distance of an independent
// realization); a median, as the sub-windows overlap and share the exemplar's noise: their
// upper quantiles come out too low (fidelity.hpp's band is measured instead). How
// well this holds on simulated processes: docs/lab/scorecard/README.md ("Fidelity, calibrated").
#include <cstdint>
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

// `count` sub-windows of side fraction `side` of `d`'s sides (the exemplar's aspect), placed
// uniformly at random inside `d` by `seed` (the same windows for the same arguments).
std::vector<Domain> random_subwindows(const Domain& d, double side, int count, uint64_t seed);

// The factor that brings a distance measured between a sub-window of area `sub_area` and the
// whole exemplar (`exemplar_area`) to an independent pattern of `output_area` (all in one unit).
double spread_scale(double sub_area, double exemplar_area, double output_area);

struct Spread {
  size_t draws = 0;   // finite scaled distances
  double median = 0;  // their median: the spread
};

// The spread of the scaled distances (non-finite ones left out); draws = 0 when none is finite.
Spread spread_of(const std::vector<double>& scaled);

}  // namespace ppsynth
