// A build without cairo (cmake -DPPSYNTH_WITH_CAIRO=OFF, for a machine that has no cairo
// headers, such as a GPU node that cannot install packages): compiled instead of the drawing
// files of core/render. Every figure is left out: the
// first one says so as a warning, naming the option; each left-out file is logged at debug
// level. Everything else a command does (point files, run.json, metrics) is written as usual.
// The layout helpers answer as if every plot fitted: they only size figures that are not drawn.
#include <algorithm>
#include <atomic>

#include "core/log.hpp"
#include "core/render/gray_png.hpp"
#include "core/render/image_file.hpp"
#include "core/render/image_grid.hpp"
#include "core/render/plot_curves.hpp"
#include "core/render/plot_points.hpp"
#include "core/render/plot_spectrum.hpp"
#include "core/render/plot_strips.hpp"

namespace ppsynth {

namespace {

void left_out(const std::string& path) {
  render::image_kind_for(path);  // a bad extension is still an error, as with cairo
  static std::atomic<bool> said{false};
  if (!said.exchange(true))
    spdlog::warn("plots are left out: this ppsynth was built without cairo (-DPPSYNTH_WITH_CAIRO=OFF); {} and every "
                 "later figure are not written",
                 path);
  spdlog::debug("plot left out (no cairo): {}", path);
}

}  // namespace

int readable_plot_px(const std::vector<const PointSet*>&, int base_px) { return base_px; }
void plot_points(const std::string& path, const PointSet&, const PointStyle&, int) { left_out(path); }
void plot_panels(const std::string& path, const std::vector<std::pair<std::string, PointSet>>&, const PointStyle&, int, int) {
  left_out(path);
}
void plot_curves(const std::string& path, const CurvePlot&, int, int) { left_out(path); }
void plot_curve_grid(const std::string& path, const std::vector<CurvePlot>&, int, int, int) { left_out(path); }
CurveGridLayout curve_grid_layout(size_t n, int columns, int, int) {
  CurveGridLayout l;
  l.shown = std::max<size_t>(n, 1);
  l.columns = columns <= 0 ? static_cast<int>(l.shown) : columns;
  l.rows = static_cast<int>((l.shown + l.columns - 1) / l.columns);
  return l;
}
bool curve_grid_fits(size_t, int, int, int) { return true; }
void plot_image_grid(const std::string& path, const std::vector<GrayImage>&, int, int, bool, ColorMap) {
  left_out(path);
}
void plot_spectrum(const std::string& path, const Periodogram&, const std::string&, int) { left_out(path); }
void plot_strips(const std::string& path, const StripPlot&, int) { left_out(path); }
void write_gray_png(const std::string& path, const GrayImage&, double, double) { left_out(path); }

}  // namespace ppsynth
