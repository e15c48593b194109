#pragma once
// method.window, typed: the memory budget of a rectangle output's grid ("output": {"size"} or
// {"points"}, or a rectangular exemplar) and how a canvas past it is cut into windows
// (optim/gabor/windows/window_plan.hpp), each key declared once in its table (window_options.cpp).
#include <optional>
#include <vector>

#include "core/config/params.hpp"

namespace ppsynth {

struct WindowOptions {
  int pixels = 640;               // a grid holds at most pixels x pixels positions, in any aspect
  std::optional<double> margin;   // exemplar units on each side of an interior; none: "auto"
  int receptive_field = 16;       // the network's half-width in grid positions ("auto" margins)
  bool statistics_in_output = false;  // the losses measure the grid's part inside the output only

  static const ParamTable<WindowOptions>& params();
  // The "auto" margin for sigma stages of `sigmas` on grids of `res` positions per exemplar
  // unit: the maps' reach (3 sigma) plus the receptive field, where they reach farthest.
  double auto_margin(const std::vector<double>& sigmas, const std::vector<int>& res) const;
};

}  // namespace ppsynth
