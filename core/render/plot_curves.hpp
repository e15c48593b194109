#pragma once
// Line plots with axes, ticks, grid and legend: PCF curves (exemplar vs output), loss
// curves (log y), radially averaged power spectra. Series colors follow the Tableau-10
// palette in order; `dashed` series (e.g. the exemplar reference) use a dash pattern.
// Non-finite values, values beyond +-1e150 (and y <= 0 on a log axis) break the line
// instead of failing.
// Output format by extension: .png, .svg, .pdf; atomic writes.
#include <string>
#include <vector>

namespace ppsynth {

struct Series {
  std::string label;
  std::vector<double> x, y;  // same length (InputError otherwise)
  bool dashed = false;
  int color = -1;            // palette index; -1: the series' own index. An empty label: no legend entry
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
// Any number of plots renders within the image limits (render/canvas.hpp: 16384 px a side;
// a grid at most 16 megapixels) and never throws for its count (curve_grid_layout): when the grid as asked
// does not fit, it is laid out nearly square with more columns, its cells shrunk down to 60 %
// (fonts with them); if even that does not fit, the first `shown` plots are drawn and a title
// line above them says how many were left out (and which, by title).
void plot_curve_grid(const std::string& path, const std::vector<CurvePlot>& plots, int columns,
                     int cell_w = 360, int cell_h = 260);

struct CurveGridLayout {
  int columns = 1, rows = 1;
  double scale = 1;   // cell size factor (fonts scale with it)
  size_t shown = 0;   // plots drawn: the first `shown`; < n means some are left out
  int header = 0;     // px of the "left out" title line (0 when all are shown)
  int width = 0, height = 0;  // image size in px
};
// The layout plot_curve_grid uses for n plots: cheap (no drawing), so a caller can say up
// front what a figure will show. curve_grid_fits: all n plots are drawn (perhaps smaller).
CurveGridLayout curve_grid_layout(size_t n, int columns, int cell_w = 360, int cell_h = 260);
bool curve_grid_fits(size_t n, int columns, int cell_w = 360, int cell_h = 260);

}  // namespace ppsynth
