#pragma once
// Periodicity: does the output repeat with the exemplar's period, as a tiled copy does?
//
// A pattern that repeats with the period (Px, Py) (the exemplar's width and height in output
// units) has its periodogram (periodogram.hpp) concentrated on the lattice of the period's
// harmonics, f = (m / Px, n / Py): there the copies add up in phase, between them they cancel.
// A pattern that does not repeat has no reason to prefer those frequencies. So, with the output
// in period units (x / Px, y / Py: the harmonics are whole cycles per period), on the grid of
// half-cycle steps up to `harmonics` cycles (plus one step, so that every harmonic has
// neighbours on both sides):
//
//   ratio = median of P over the harmonics (m, n) != (0, 0), |m|, |n| <= harmonics
//           / median of P over the grid's frequencies between them (a half-integer coordinate)
//
// Every frequency's periodogram is about its structure factor times an exponential variable,
// and the harmonics sit among the frequencies between them, so for a pattern that does not
// repeat the ratio is about 1 whatever its structure (clustered, regular, uniform); a tiled
// copy puts ~0 between the harmonics (exactly 0 on a whole number of periods), so its ratio
// is as high as the floor lets it be: the denominator is at least 1e-3 of the grid's mean
// power (periodogram.hpp's floor for spectrum_peak).
// Medians, not means: a jittered grid whose cells divide the exemplar's window has Bragg
// peaks on a few of the harmonics; a median ignores them.
//
// The output is flagged periodic when the ratio reaches `periodic_ratio`. The threshold and
// its measured false-alarm rate: docs/explanation/scorecard.md.
// The period must be the copy's to within a few per cent (the doc says how the ratio falls):
// off by more, the high harmonics drift onto the frequencies between. eval's zoom from the
// densities is exact for whole tiles; --zoom gives it for cut ones.
// What it cannot see: a copy rotated, mirrored or rescaled; a copy that does not repeat (one
// period or less: nothing repeats, the novelty line sees the copy);
// an exemplar that is itself periodic at its window (a perfect lattice that tiles it): every
// realization of that process repeats too.
// Cost: one periodogram of the output on (4 harmonics + 3)^2 frequencies, O(N harmonics^2).
#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth {

struct PeriodicityOptions {
  int harmonics = 8;            // highest harmonic of the period along each axis
  double periodic_ratio = 3.0;  // flagged periodic from this ratio
};

// InputError (naming eval's flag) for harmonics outside 1..64 or a ratio that is not > 1.
void check_periodicity_options(const PeriodicityOptions& opt);

struct PeriodicityRatio {
  double ratio = 0;        // median at the harmonics over the median between them
  double harmonic_median = 0, between_median = 0;
  size_t harmonics = 0, between = 0;  // frequencies of each kind in the half plane
};

// `ps` against the period `period` (its coordinate units).
PeriodicityRatio periodicity_ratio(const PointSet& ps, Vec2 period, int harmonics);

// The scorecard's periodicity line: the output (output units) against the exemplar's window
// times `zoom` (output units per exemplar unit).
// { "measures", "harmonics", "period": [Px, Py] (output units), "periods": [output width /
//   Px, height / Py], "ratio", "harmonic_median", "between_median", "periodic_ratio",
//   "periodic" (ratio >= periodic_ratio; null below 2 output points) }
nlohmann::json periodicity_report(const PointSet& exemplar, const PointSet& output, double zoom,
                                  const PeriodicityOptions& opt);

}  // namespace ppsynth
