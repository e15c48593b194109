#pragma once
// Strip plots: one column per group (a configuration, a method), one dot per sample (a seed),
// over a box from the first to the third quartile with the median, whiskers to the extremes.
// Made for statistics over seeds (experiments/gather/gather.hpp), where five dots say more than a
// mean: the reader sees the spread and every outlier. An optional reference value (a published
// output's) and a bound (e.g. 1.25 x the reference) are drawn as horizontal lines across all
// groups. Non-finite values are left out of the column (and counted in its label). Labels too
// long for their column are lettered (A, B, ...) and written whole in the legend below, the
// image widened to them (labels of one sweep differ at their end, where an ellipsis would cut);
// any number of groups fits within render's image limits (thinner columns past ~135).
// Output format by extension: .png, .svg, .pdf; atomic writes (render/canvas.hpp).
#include <optional>
#include <string>
#include <vector>

namespace ppsynth {

struct StripGroup {
  std::string label;
  std::vector<double> values;
};

struct StripPlot {
  std::string title, ylabel;
  std::vector<StripGroup> groups;
  std::optional<double> reference;  // drawn as a solid line
  std::string reference_label;
  std::optional<double> bound;      // drawn as a dashed line
  std::string bound_label;
};

// The box and whiskers are core/metrics/summary_stats.hpp's summarize(values).
void plot_strips(const std::string& path, const StripPlot& plot, int height_px = 380);

}  // namespace ppsynth
