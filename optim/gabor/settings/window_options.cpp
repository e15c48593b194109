#include "optim/gabor/settings/window_options.hpp"

#include <algorithm>

namespace ppsynth {

// Rectangle outputs (optim/gabor/windows/window_plan.hpp): the canvas is one grid of rows x
// columns positions when they number at most `pixels` x `pixels` (the budget: an iteration's
// memory goes with its grid positions, core/memory_budget.hpp's estimate in
// gabor_resolution.cpp), whatever its aspect; past it, the fewest rectangular windows of at
// most that many, with a margin of 3 sigma_max + `receptive_field` positions (the network's
// half-width) on each side of an interior (null or "auto"), or a length in exemplar units.
// `statistics`: where the losses measure the output's features: "grid" (the whole window grid,
// as the paper measures its square) or "output" (the grid's part inside the output rectangle:
// the pad of a clean or context border is seen by the maps but not measured, so its outer
// edge, where plane maps lose a point's influence, asks nothing of the rectangle).
const ParamTable<WindowOptions>& WindowOptions::params() {
  using W = WindowOptions;
  static const ParamTable<W> t("method.window", {
      param("pixels", &W::pixels, "int [16, 8192]", "a grid holds at most pixels x pixels positions, in any aspect"),
      param("margin", &W::margin, "[0, inf)", "exemplar units on each side of a window's interior; null or \"auto\": the maps' reach"),
      param("receptive_field", &W::receptive_field, "int [0, 1000]", "the network's half-width in grid positions (\"auto\" margins)"),
      choice("statistics", &W::statistics_in_output, {{"grid", false}, {"output", true}},
             "where the losses measure: the whole window grid, or its part inside the output"),
  });
  return t;
}

double WindowOptions::auto_margin(const std::vector<double>& sigmas, const std::vector<int>& res) const {
  double r = 0;
  for (size_t i = 0; i < sigmas.size(); ++i) r = std::max(r, 3 * sigmas[i] + receptive_field / static_cast<double>(res[i]));
  return r;
}

}  // namespace ppsynth
