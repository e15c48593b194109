#include "core/render/plot_curves.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/log.hpp"
#include "core/render/canvas.hpp"
#include "core/render/palette.hpp"
#include "core/render/plot_frame.hpp"

namespace ppsynth {

namespace {

using namespace render;

int color_of(const Series& s, size_t k) { return s.color >= 0 ? s.color : static_cast<int>(k); }

void check_series(const CurvePlot& plot, const std::string& path) {
  for (const auto& s : plot.series)
    if (s.x.size() != s.y.size())
      throw InputError("plot " + path + ": series '" + s.label + "' has " + std::to_string(s.x.size()) +
                       " x values but " + std::to_string(s.y.size()) + " y values");
}

bool usable(double x, double y, bool log_y) { return plottable(x) && plottable(y) && (!log_y || y > 0); }

// An empty or degenerate range [v, v] (also at 1e20, where v +- 0.5 == v) gets a width.
void widen(double& lo, double& hi) {
  if (hi - lo > std::abs(lo) * 1e-12 && hi - lo > 0) return;
  const double w = std::max(0.5, std::abs(lo) * 1e-6);
  lo -= w;
  hi += w;
}

// The axes' ranges and ticks: every usable point inside, the y range out to whole tick steps
// (log: decades) so that no curve touches the frame.
struct CurveAxes {
  double xlo = 0, xhi = 1, ylo = 0, yhi = 1;
  std::vector<double> xt, yt;
  bool has_data = false;
};

CurveAxes curve_axes(const CurvePlot& plot) {
  CurveAxes a;
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  for (const auto& s : plot.series)
    for (size_t i = 0; i < s.x.size(); ++i)
      if (usable(s.x[i], s.y[i], plot.log_y)) {
        xlo = std::min(xlo, s.x[i]), xhi = std::max(xhi, s.x[i]);
        ylo = std::min(ylo, s.y[i]), yhi = std::max(yhi, s.y[i]);
      }
  a.has_data = xlo <= xhi;
  if (!a.has_data) xlo = 0, xhi = 1, ylo = plot.log_y ? 0.1 : 0, yhi = 1;
  widen(xlo, xhi);
  // Curves that start just above 0 (PCF radii from 0.01 r_max) get an axis from 0.
  if (a.has_data && xlo > 0 && xlo < 0.05 * (xhi - xlo)) xlo = 0;
  if (plot.log_y) {
    if (yhi == ylo) ylo /= 2, yhi *= 2;
    // 4% headroom in log space; widen to one decade so at least one tick shows.
    double l0 = std::log10(ylo), l1 = std::log10(yhi);
    const double pad = 0.04 * (l1 - l0);
    l0 -= pad, l1 += pad;
    if (l1 - l0 < 1) {
      const double mid = (l0 + l1) / 2;
      l0 = mid - 0.5, l1 = mid + 0.5;
    }
    ylo = std::pow(10.0, l0), yhi = std::pow(10.0, l1);
    a.yt = log_ticks(ylo, yhi);
  } else {
    widen(ylo, yhi);
    // Expand to the enclosing tick steps so the curve never touches the frame.
    a.yt = nice_ticks(ylo, yhi, 5);
    const double step = a.yt.size() >= 2 ? a.yt[1] - a.yt[0] : (yhi - ylo);
    ylo = std::floor(ylo / step + 1e-9) * step;
    yhi = std::ceil(yhi / step - 1e-9) * step;
    if (yhi - ylo < 1e-12) yhi = ylo + step;
    widen(ylo, yhi);
    a.yt = nice_ticks(ylo, yhi, 5);
  }
  widen(xlo, xhi);
  a.xt = nice_ticks(xlo, xhi, 6);
  a.xlo = xlo, a.xhi = xhi, a.ylo = ylo, a.yhi = yhi;
  return a;
}

// One series as a line through its usable points (a gap where a point is not), in `color`;
// a series with one usable point is a dot.
void draw_series(cairo_t* cr, const Series& s, int color, bool log_y, const std::function<double(double)>& X,
                 const std::function<double(double)>& Y) {
  set_color(cr, class_color(color));
  cairo_set_line_width(cr, 1.8);
  if (s.dashed) {
    const double d[] = {6, 4};
    cairo_set_dash(cr, d, 2, 0);
  } else {
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  bool pen = false;
  size_t drawn = 0;
  for (size_t i = 0; i < s.x.size(); ++i) {
    if (!usable(s.x[i], s.y[i], log_y)) {
      pen = false;  // gap
      continue;
    }
    if (pen)
      cairo_line_to(cr, X(s.x[i]), Y(s.y[i]));
    else
      cairo_move_to(cr, X(s.x[i]), Y(s.y[i]));
    pen = true;
    ++drawn;
  }
  cairo_stroke(cr);
  if (drawn == 1) {  // a single point would be invisible as a line
    for (size_t i = 0; i < s.x.size(); ++i)
      if (usable(s.x[i], s.y[i], log_y)) cairo_arc(cr, X(s.x[i]), Y(s.y[i]), 2.5, 0, 2 * M_PI);
    cairo_fill(cr);
  }
}

// Draws one plot inside the box (bx, by, bw, bh).
void draw_plot(cairo_t* cr, const CurvePlot& plot, double bx, double by, double bw, double bh) {
  const CurveAxes axes = curve_axes(plot);
  const double xlo = axes.xlo, xhi = axes.xhi, ylo = axes.ylo, yhi = axes.yhi;

  // --- layout ---
  double ytw = 0;
  for (double t : axes.yt) ytw = std::max(ytw, measure_text(tick_label(t), kChartTickFont));
  std::vector<LegendItem> legend;
  for (size_t k = 0; k < plot.series.size(); ++k)
    if (!plot.series[k].label.empty())
      legend.push_back({plot.series[k].label, class_color(color_of(plot.series[k], k)),
                        plot.series[k].dashed ? Marker::DashedLine : Marker::Line});
  const double left = bx + kChartPad + (plot.ylabel.empty() ? 0 : kChartLabelFont * 1.5) + ytw + 8;
  const double right = bx + bw - kChartPad;
  const double top = by + (plot.title.empty() ? kChartPad : kChartTitleFont * 2.2);
  const double leg_h = legend_height(legend, right - left, kChartLegendFont);
  const double bottom = by + bh - kChartPad - leg_h - (plot.xlabel.empty() ? 0 : kChartLabelFont * 1.6) - kChartTickFont * 1.6;
  const double pw = right - left, ph = bottom - top;
  if (pw < 10 || ph < 10) return;  // too small to draw anything meaningful

  const std::function<double(double)> X = [&](double x) { return left + (x - xlo) / (xhi - xlo) * pw; };
  const std::function<double(double)> Y = [&](double y) {
    const double t = plot.log_y ? (std::log10(y) - std::log10(ylo)) / (std::log10(yhi) - std::log10(ylo))
                                : (y - ylo) / (yhi - ylo);
    return bottom - t * ph;
  };

  // --- title and axis labels ---
  set_color(cr, kText);
  if (!plot.title.empty()) draw_text(cr, plot.title, left, by + kChartTitleFont * 1.5, kChartTitleFont, HAlign::Left, VAlign::Baseline, true);
  if (!plot.xlabel.empty())
    draw_text(cr, plot.xlabel, left + pw / 2, bottom + kChartTickFont * 1.6 + 4, kChartLabelFont, HAlign::Center, VAlign::Top);
  if (!plot.ylabel.empty())
    draw_text(cr, plot.ylabel, bx + kChartPad, top + ph / 2, kChartLabelFont, HAlign::Center, VAlign::Top, false, -M_PI / 2);

  // --- grid, ticks ---
  cairo_save(cr);
  cairo_set_line_width(cr, 1);
  for (double t : axes.xt) {
    set_color(cr, kGrid);
    cairo_move_to(cr, std::round(X(t)) + 0.5, top);
    cairo_line_to(cr, std::round(X(t)) + 0.5, bottom);
    cairo_stroke(cr);
    set_color(cr, kText);
    draw_text(cr, tick_label(t), X(t), bottom + 5, kChartTickFont, HAlign::Center, VAlign::Top);
  }
  draw_y_grid(cr, axes.yt, left, right, Y);
  set_color(cr, kAxis);
  cairo_rectangle(cr, std::round(left) + 0.5, std::round(top) + 0.5, std::round(pw), std::round(ph));
  cairo_stroke(cr);
  cairo_restore(cr);

  // --- curves, clipped to the frame ---
  cairo_save(cr);
  cairo_rectangle(cr, left, top, pw, ph);
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  for (size_t k = 0; k < plot.series.size(); ++k) draw_series(cr, plot.series[k], color_of(plot.series[k], k), plot.log_y, X, Y);
  cairo_restore(cr);
  if (!axes.has_data) {
    set_color(cr, kAxis);
    draw_text(cr, "(no data)", left + pw / 2, top + ph / 2, kChartLabelFont, HAlign::Center, VAlign::Middle);
  }

  draw_legend(cr, legend, left, by + bh - kChartPad - leg_h, right - left, kChartLegendFont);
}

}  // namespace

void plot_curves(const std::string& path, const CurvePlot& plot, int width_px, int height_px) {
  render::image_kind_for(path);
  check_series(plot, path);
  render::render_to_file(path, width_px, height_px,
                         [&](cairo_t* cr) { draw_plot(cr, plot, 0, 0, width_px, height_px); });
}

namespace {
constexpr double kMinGridScale = 0.6;
constexpr int kGridHeader = 30;
// A grid of many plots stays a figure one can open: 16 megapixels (64 MB as a raster).
constexpr double kGridMaxPixels = 16.0e6;

bool fits(double w, double h) { return render::image_size_ok(w, h) && w * h <= kGridMaxPixels; }
}  // namespace

CurveGridLayout curve_grid_layout(size_t n, int columns, int cell_w, int cell_h) {
  CurveGridLayout l;
  if (cell_w < 1 || cell_h < 1) return l;  // plot_curve_grid refuses such cells
  n = std::max<size_t>(n, 1);
  // As asked.
  {
    const size_t cols = columns <= 0 ? n : std::min<size_t>(static_cast<size_t>(columns), n);
    const size_t rows = (n + cols - 1) / cols;
    if (fits(static_cast<double>(cols) * cell_w, static_cast<double>(rows) * cell_h)) {
      l.columns = static_cast<int>(cols), l.rows = static_cast<int>(rows), l.shown = n;
      l.width = l.columns * cell_w, l.height = l.rows * cell_h;
      return l;
    }
  }
  // Nearly square, cells shrinking to kMinGridScale; then the first plots that fit.
  for (int step = 0;; ++step) {
    const double scale = std::max(kMinGridScale, 1.0 - 0.05 * step);
    const double w = cell_w * scale, h = cell_h * scale;
    const bool last = scale <= kMinGridScale;
    const double header = last ? kGridHeader : 0;
    const size_t max_cols = static_cast<size_t>(std::max(1.0, std::floor(render::kMaxImageSide / w)));
    const size_t max_rows = static_cast<size_t>(std::max(1.0, std::floor((render::kMaxImageSide - header) / h)));
    // Capacity: at most max_cols x max_rows cells and kMaxImagePixels.
    size_t cap = 0;
    size_t best_cols = 1;
    for (size_t cols = 1; cols <= max_cols; ++cols) {
      const double area_rows = std::floor((kGridMaxPixels / (cols * w) - header) / h);
      const size_t rows = std::min(max_rows, static_cast<size_t>(std::max(0.0, area_rows)));
      if (cols * rows > cap) cap = cols * rows, best_cols = cols;
    }
    if (n <= cap || last) {
      const size_t shown = std::min(n, std::max<size_t>(cap, 1));
      // Nearly square image for the plots shown, within the limits.
      size_t cols = static_cast<size_t>(std::ceil(std::sqrt(shown * h / w)));
      cols = std::clamp<size_t>(cols, 1, max_cols);
      auto rows_for = [&](size_t c) { return (shown + c - 1) / c; };
      while (cols < max_cols && !fits(cols * w, rows_for(cols) * h + (shown < n ? header : 0))) ++cols;
      if (!fits(cols * w, rows_for(cols) * h + (shown < n ? header : 0))) cols = best_cols;
      l.columns = static_cast<int>(cols);
      l.rows = static_cast<int>(rows_for(cols));
      l.scale = scale;
      l.shown = shown;
      l.header = shown < n ? kGridHeader : 0;
      l.width = static_cast<int>(std::ceil(cols * w));
      l.height = static_cast<int>(std::ceil(l.rows * h)) + l.header;
      return l;
    }
  }
}

bool curve_grid_fits(size_t n, int columns, int cell_w, int cell_h) {
  return curve_grid_layout(n, columns, cell_w, cell_h).shown >= std::max<size_t>(n, 1);
}

void plot_curve_grid(const std::string& path, const std::vector<CurvePlot>& plots, int columns, int cell_w,
                     int cell_h) {
  render::image_kind_for(path);
  if (plots.empty()) throw InputError("plot " + path + ": no plots in the grid");
  if (cell_w < 40 || cell_h < 40 || cell_w > render::kMaxImageSide || cell_h > render::kMaxImageSide)
    throw InputError("plot " + path + ": grid cells must be 40.." + std::to_string(render::kMaxImageSide) +
                     " px (got " + std::to_string(cell_w) + "x" + std::to_string(cell_h) + ")");
  for (const auto& p : plots) check_series(p, path);
  const CurveGridLayout l = curve_grid_layout(plots.size(), columns, cell_w, cell_h);
  if (l.shown < plots.size())
    spdlog::warn("plot {}: {} plots do not fit one image; drawing the first {}", path, plots.size(), l.shown);
  render::render_to_file(path, l.width, l.height, [&](cairo_t* cr) {
    if (l.header > 0) {
      std::string note = "showing the first " + std::to_string(l.shown) + " of " + std::to_string(plots.size()) +
                         " plots; " + std::to_string(plots.size() - l.shown) + " left out: " +
                         plots[l.shown].title;
      for (size_t i = l.shown + 1; i < plots.size() && i < l.shown + 3; ++i) note += ", " + plots[i].title;
      if (plots.size() - l.shown > 3) note += ", ...";
      set_color(cr, kText);
      draw_text(cr, note, kChartPad, l.header / 2.0, 13, HAlign::Left, VAlign::Middle, true);
    }
    for (size_t i = 0; i < l.shown; ++i) {
      cairo_save(cr);
      cairo_translate(cr, (i % l.columns) * cell_w * l.scale, l.header + (i / l.columns) * cell_h * l.scale);
      cairo_scale(cr, l.scale, l.scale);
      draw_plot(cr, plots[i], 0, 0, cell_w, cell_h);
      cairo_restore(cr);
    }
  });
}

}  // namespace ppsynth
