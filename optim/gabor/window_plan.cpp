#include "optim/gabor/window_plan.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "optim/gabor/gabor_pipeline.hpp"

namespace ppsynth {

namespace {

struct AxisWindows {
  std::vector<double> grid0;             // each window grid's start
  std::vector<double> interior0, interior1;
};

// Windows of `side` along [c0, c1]: the first starts at c0, the last ends at c1, the rest
// evenly between; the interiors split each overlap in the middle.
AxisWindows along_axis(double c0, double c1, double side, double margin) {
  AxisWindows a;
  const double L = c1 - c0;
  const int n = L <= side * (1 + 1e-12) ? 1 : 1 + static_cast<int>(std::ceil((L - side) / (side - 2 * margin) - 1e-9));
  for (int i = 0; i < n; ++i) a.grid0.push_back(n == 1 ? c0 : c0 + i * (L - side) / (n - 1));
  for (int i = 0; i < n; ++i) {
    a.interior0.push_back(i == 0 ? c0 : 0.5 * (a.grid0[i - 1] + side + a.grid0[i]));
    a.interior1.push_back(i == n - 1 ? c1 : 0.5 * (a.grid0[i] + side + a.grid0[i + 1]));
  }
  return a;
}

}  // namespace

bool windows_fit(const Domain& canvas, double max_side, double margin) {
  const double side = std::min({max_side, canvas.width(), canvas.height()});
  // One window over the whole canvas has no neighbor to protect: any margin will do.
  const bool one_window = canvas.width() <= side * (1 + 1e-12) && canvas.height() <= side * (1 + 1e-12);
  return one_window || side > 2 * margin * 1.25;
}

WindowLayout window_layout(const Domain& canvas, const Domain& moving_area, double max_side, double margin, double reach, const std::string& key) {
  WindowLayout w;
  w.canvas = canvas;
  w.side = std::min({max_side, canvas.width(), canvas.height()});
  w.margin = margin;
  w.reach = reach;
  if (!windows_fit(canvas, max_side, margin))
    throw config_error(key, "a window of " + std::to_string(w.side) + " exemplar units cannot hold two margins of " +
                                std::to_string(margin) + " and an interior (the maps' reach and the network's receptive " +
                                "field); use larger windows or a larger output");
  const AxisWindows ax = along_axis(canvas.x0, canvas.x1, w.side, margin), ay = along_axis(canvas.y0, canvas.y1, w.side, margin);
  w.nx = static_cast<int>(ax.grid0.size());
  w.ny = static_cast<int>(ay.grid0.size());
  for (int j = 0; j < w.ny; ++j)
    for (int i = 0; i < w.nx; ++i) {
      StageWindow s;
      s.grid = Domain{ax.grid0[i], ay.grid0[j], ax.grid0[i] + w.side, ay.grid0[j] + w.side};
      s.interior = Domain{ax.interior0[i], ay.interior0[j], ax.interior1[i], ay.interior1[j]};
      s.movable = Domain{std::max(s.interior.x0, moving_area.x0), std::max(s.interior.y0, moving_area.y0),
                         std::min(s.grid.x1, moving_area.x1), std::min(s.grid.y1, moving_area.y1)};
      s.context = Domain{s.grid.x0 - reach, s.grid.y0 - reach, s.grid.x1 + reach, s.grid.y1 + reach};
      s.index = static_cast<int>(w.windows.size());
      s.count = w.nx * w.ny;
      w.windows.push_back(s);
    }
  return w;
}

SynthesisPlan window_plan(const PointSet& exemplar, const GaborSettings& s, const WindowLayout& layout) {
  const std::vector<std::vector<size_t>> none(exemplar.num_classes());
  const SynthesisPlan per_window = class_sigma_plan(exemplar, s, none);
  SynthesisPlan plan;
  for (const auto& w : layout.windows) {
    const auto geometry = std::make_shared<WindowGeometry>(w);
    for (Stage st : per_window) {
      st.label = "window " + std::to_string(w.index + 1) + "/" + std::to_string(w.count) + ", " + st.label;
      st.group += w.index * exemplar.num_classes();
      st.geometry = geometry;
      plan.push_back(std::move(st));
    }
  }
  return plan;
}

}  // namespace ppsynth
