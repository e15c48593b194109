#include "optim/gabor/settings/window_size.hpp"

#include <algorithm>
#include <cmath>

#include "models/feature_grid.hpp"

namespace ppsynth {

namespace {

// The side of n windows covering a length L with overlaps of exactly 2 margins (the least
// area that keeps them): n side - (n - 1) 2 margin = L.
double side_of(double L, int n, double margin) { return n == 1 ? L : (L + 2 * margin * (n - 1)) / n; }

// The most windows along an axis of length L: each must keep an interior of more than half a
// margin beyond its two margins (side > 2.5 margin) and a grid of at least 8 positions.
int most_windows(double L, double margin, int res) {
  int n = 1;
  while (side_of(L, n + 1, margin) > 2.5 * margin && side_of(L, n + 1, margin) * res >= 8) ++n;
  return n;
}

}  // namespace

std::pair<int, int> window_grid(double width, double height, int res) {
  const int cols = std::max(8, static_cast<int>(std::lround(width * res)));
  return {cols, grid_rows(cols, height / width)};
}

std::optional<WindowSize> window_size(const Domain& canvas, double max_positions, int res, double margin) {
  const double W = canvas.width(), H = canvas.height();
  auto fits = [&](double w, double h) {
    const auto [cols, rows] = window_grid(w, h, res);
    return static_cast<double>(cols) * rows <= max_positions;
  };
  if (fits(W, H)) return WindowSize{W, H, 1, 1};
  // Every count along x with the fewest rows of windows that fit it (more rows, smaller
  // windows: a bisection): the first of the fewest windows, then of the least area, wins (x
  // first: the same canvas always gets the same plan).
  std::optional<WindowSize> best;
  const int most_x = most_windows(W, margin, res), most_y = most_windows(H, margin, res);
  for (int nx = 1; nx <= most_x; ++nx) {
    const double w = side_of(W, nx, margin);
    if (!fits(w, side_of(H, most_y, margin))) continue;
    int lo = 0, hi = most_y;  // fits at hi, not at lo (0: none)
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      (fits(w, side_of(H, mid, margin)) ? hi : lo) = mid;
    }
    const WindowSize s{w, side_of(H, hi, margin), nx, hi};
    const long count = static_cast<long>(nx) * hi, best_count = best ? static_cast<long>(best->nx) * best->ny : 0;
    if (!best || count < best_count || (count == best_count && s.width * s.height < best->width * best->height)) best = s;
  }
  return best;
}

}  // namespace ppsynth
