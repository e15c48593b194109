#include "optim/gabor/windows/window_plan.hpp"

#include <algorithm>
#include <cmath>

namespace ppsynth {

namespace {

struct AxisWindows {
  std::vector<double> grid0;             // each window grid's start
  std::vector<double> interior0, interior1;
};

// `n` windows of `side` along [c0, c1]: the first starts at c0, the last ends at c1, the rest
// evenly between; the interiors split each overlap in the middle.
AxisWindows along_axis(double c0, double c1, double side, int n) {
  AxisWindows a;
  const double L = c1 - c0;
  for (int i = 0; i < n; ++i) a.grid0.push_back(n == 1 ? c0 : c0 + i * (L - side) / (n - 1));
  for (int i = 0; i < n; ++i) {
    a.interior0.push_back(i == 0 ? c0 : 0.5 * (a.grid0[i - 1] + side + a.grid0[i]));
    a.interior1.push_back(i == n - 1 ? c1 : 0.5 * (a.grid0[i] + side + a.grid0[i + 1]));
  }
  return a;
}

}  // namespace

WindowLayout window_layout(const Domain& canvas, const Domain& moving_area, const WindowSize& size, double margin, double reach) {
  WindowLayout w;
  w.canvas = canvas;
  w.size = size;
  w.margin = margin;
  w.reach = reach;
  const AxisWindows ax = along_axis(canvas.x0, canvas.x1, size.width, size.nx),
                    ay = along_axis(canvas.y0, canvas.y1, size.height, size.ny);
  w.nx = size.nx;
  w.ny = size.ny;
  for (int j = 0; j < w.ny; ++j)
    for (int i = 0; i < w.nx; ++i) {
      StageWindow s;
      // One window along an axis is the canvas's extent exactly (not x0 + width, a rounding away).
      s.grid = Domain{ax.grid0[i], ay.grid0[j], w.nx == 1 ? canvas.x1 : ax.grid0[i] + size.width,
                      w.ny == 1 ? canvas.y1 : ay.grid0[j] + size.height};
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
  // Each window's groups after the previous window's: K class groups, then the after-all kinds'
  // (the revisit) in groups of K of their own.
  int groups = 0;
  for (const Stage& st : per_window) groups = std::max(groups, st.group + 1);
  SynthesisPlan plan;
  for (const auto& w : layout.windows) {
    const auto geometry = std::make_shared<WindowGeometry>(w);
    for (Stage st : per_window) {
      if (w.count > 1) st.label = "window " + std::to_string(w.index + 1) + "/" + std::to_string(w.count) + ", " + st.label;
      st.group += w.index * groups;
      st.geometry = geometry;
      plan.push_back(std::move(st));
    }
  }
  return plan;
}

}  // namespace ppsynth
