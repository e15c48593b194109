#pragma once
// How large the windows of a rectangle output are and how many (optim/gabor/windows/window_plan.hpp
// lays them out): the fewest within the memory budget. The settings hold the answer
// (GaborSettings::window), so it lives below them.
#include <optional>
#include <utility>

#include "core/point_set.hpp"

namespace ppsynth {

// The windows' size and count: nx x ny windows of width x height exemplar units.
struct WindowSize {
  double width = 0, height = 0;
  int nx = 1, ny = 1;
};

// The grid of a window of `width` x `height` exemplar units at `res` positions per unit:
// {columns, rows} (rows at the columns' spacing, models/feature_grid.hpp; at least 8 columns).
std::pair<int, int> window_grid(double width, double height, int res);

// The fewest windows (then the least area among as many) whose grids at `res` positions per
// unit hold at most `max_positions` each and cover `canvas` with overlaps of >= 2 margins;
// each side cut into several windows keeps an interior of more than half a margin. The
// whole canvas when it fits. None when no window that small can hold its margins.
std::optional<WindowSize> window_size(const Domain& canvas, double max_positions, int res, double margin);

}  // namespace ppsynth
