#pragma once
// Line plots with axes, ticks, grid and legend: PCF curves (exemplar vs output), loss
// curves (log y), radially averaged power spectra. Series colours follow the Tableau-10
// palette in order; `dashed` series (e.g. the exemplar reference) use a dash pattern.
// Non-finite y values (and y <= 0 on a log axis) break the line instead of failing.
// Output format by extension: .png, .svg, .pdf; atomic writes.
#include <string>
#include <vector>

namespace ppsynth {

struct Series {
  std::string label;
  std::vector<double> x, y;  // same length (InputError otherwise)
  bool dashed = false;
};

struct CurvePlot {
  std::string title, xlabel, ylabel;
  bool log_y = false;
  std::vector<Series> series;
};

void plot_curves(const std::string& path, const CurvePlot& plot, int width_px = 640,
                 int height_px = 420);

// Several small plots in a grid (e.g. one PCF per class pair), `columns` per row
// (<= 0 = all in one row). Each cell is cell_w x cell_h px.
void plot_curve_grid(const std::string& path, const std::vector<CurvePlot>& plots, int columns,
                     int cell_w = 360, int cell_h = 260);

}  // namespace ppsynth
