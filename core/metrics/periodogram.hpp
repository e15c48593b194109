#pragma once
// Seams and repetition: the 2-D power spectrum (periodogram) of a point set on a square grid
// of frequencies in cycles per COORDINATE unit (for outputs in exemplar units: cycles per
// exemplar unit; for the paper's unit square: cycles per domain side):
//
//   f = (kx, ky) * step,   kx, ky in -F..F            (grid of (2F+1) x (2F+1) frequencies)
//   P(f) = | sum_j exp(-2 pi i f . (x_j - o)) - N W(f) |^2 / N
//
// with o the domain's lower-left corner and W(f) the Fourier transform of the domain's
// indicator over its area, W(f) = prod over the axes of exp(-pi i f L) sinc(f L) (L the side,
// sinc t = sin(pi t)/(pi t)). Subtracting N W(f) removes the domain's own window from the
// spectrum: on the square grid of a rectangle (a 4 x 1 strip: 1/4 cycle per unit steps along
// the short side too) the frequencies are not all whole cycles per side, and the window's
// leakage would otherwise swamp the low frequencies. At whole cycles per side W = 0, so
// there P is the classic periodogram (Heck et al. 2013); P(0) = 0 (the DC term is removed).
// Uniform random points give P ~ 1 everywhere (exponentially distributed values); blue noise
// a dark disk and a bright ring at the inverse point spacing; a pattern that repeats with a
// period T shows isolated peaks on the lattice of multiples of 1/T (tiles, seams), off the
// ring; a perfect lattice only its Bragg peaks.
//
// step: 0 = 1 / the domain's LONGER side, the finest spacing the domain resolves (a pattern
// tiled k times along that side puts its tile frequencies on every k-th column, with ~0
// between). F: the grid's half size; the highest frequency is F x step.
// Cost: O(N F^2) complex multiply-adds, on half the grid (P(-f) = P(f)), split over up to
// `threads` threads (0 = the hardware's; results do not depend on the count); memory
// O(F^2 + 2048 F). 100,000 points at F = 128: a few seconds.
#include <vector>

#include "core/point_set.hpp"

namespace ppsynth {

inline constexpr int kMaxPeriodogramFrequencies = 1024;

struct PeriodogramOptions {
  int frequencies = 128;  // F
  double step = 0;        // cycles per coordinate unit between grid frequencies; 0 = auto
  int threads = 0;        // 0 = std::thread::hardware_concurrency()
};

struct Periodogram {
  int F = 0;
  double step = 0;             // cycles per coordinate unit
  size_t points = 0;
  std::vector<double> power;   // (2F+1)^2, row-major; pixel (x, y) is f = ((x - F), (y - F)) * step
  int side() const { return 2 * F + 1; }
  double at(int kx, int ky) const { return power[static_cast<size_t>(ky + F) * side() + (kx + F)]; }
};

// InputError for an empty set, F outside 1..1024, a step that is not finite and >= 0.
Periodogram periodogram(const PointSet& ps, const PeriodogramOptions& opt = {});

// The strongest frequency against its ring: rings k = round(|(kx, ky)|) = 1..F (whole rings
// inside the grid); ratio = max over their frequencies of P(f) / median of P over f's ring
// (the median's floor is 1e-3 of the mean power over the rings: a ring more than half empty,
// as on a lattice or a tiled copy, would otherwise divide by ~0). Uniform random points score
// about 10-20 (the largest of ~50,000 exponential values over ln 2); blue noise about as
// much (its ring is bright as a whole); a tiled copy or a lattice scores orders of magnitude
// higher (its peaks stand out of rings that are otherwise dark).
struct SpectrumPeak {
  double ratio = 0;
  double power = 0, ring_median = 0;
  double fx = 0, fy = 0;  // where (cycles per coordinate unit)
  int ring = 0;           // k
};
SpectrumPeak spectrum_peak(const Periodogram& p);

}  // namespace ppsynth
