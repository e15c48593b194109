#include "optim/gabor/settings/window_options.hpp"

#include <algorithm>

#include "core/config/config.hpp"
#include "core/error.hpp"

namespace ppsynth {

namespace {
constexpr const char* k_key = "method.window";
}  // namespace

nlohmann::json WindowOptions::defaults() {
  // Rectangle outputs (optim/gabor/windows/window_plan.hpp): the canvas is one grid of rows x columns
  // positions when they number at most `pixels` x `pixels` (the budget: an iteration's memory
  // goes with its grid positions, core/memory_budget.hpp's estimate in gabor_resolution.cpp),
  // whatever its aspect; past it, the fewest rectangular windows of at most that many, with a
  // margin of 3 sigma_max + `receptive_field` positions (the network's half-width) on each
  // side of an interior (null or "auto"), or a length in exemplar units. `statistics`: where
  // the losses measure the output's features: "grid" (the
  // whole window grid, as the paper measures its square) or "output" (the grid's part inside
  // the output rectangle: the pad of a clean or context border is seen by the maps but not
  // measured, so its outer edge, where plane maps lose a point's influence, asks nothing of
  // the rectangle).
  return {{"pixels", 640}, {"margin", nullptr}, {"receptive_field", 16}, {"statistics", "grid"}};
}

nlohmann::json WindowOptions::bounds() { return {{"pixels", "int [16, 8192]"}, {"receptive_field", "int [0, 1000]"}}; }

WindowOptions WindowOptions::resolve(const nlohmann::json& block) {
  WindowOptions o;
  o.pixels = get_int(block, "pixels", k_key);
  o.receptive_field = get_int(block, "receptive_field", k_key);
  const nlohmann::json& m = block["margin"];
  if (m.is_number() && m.get<double>() >= 0)
    o.margin = m.get<double>();
  else if (!(m.is_null() || (m.is_string() && m.get<std::string>() == "auto")))
    throw config_error("method.window.margin", "expected null (\"auto\") or a length >= 0 in exemplar units");
  const nlohmann::json& st = block["statistics"];
  if (!st.is_string() || (st != "grid" && st != "output"))
    throw config_error("method.window.statistics", "expected \"grid\" or \"output\", got " + st.dump());
  o.statistics_in_output = st == "output";
  return o;
}

double WindowOptions::auto_margin(const std::vector<double>& sigmas, const std::vector<int>& res) const {
  double r = 0;
  for (size_t i = 0; i < sigmas.size(); ++i) r = std::max(r, 3 * sigmas[i] + receptive_field / static_cast<double>(res[i]));
  return r;
}

}  // namespace ppsynth
