#include "core/render/plot_strips.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/metrics/summary_stats.hpp"
#include "core/render/canvas.hpp"
#include "core/render/palette.hpp"
#include "core/render/plot_frame.hpp"

namespace ppsynth {
namespace {

using namespace render;

constexpr double kColumn = 120;  // px per group

// `text` cut to `width` px with an ellipsis.
std::string fitted(const std::string& text, double width, double font) {
  if (measure_text(text, font) <= width) return text;
  std::string s = text;
  while (!s.empty() && measure_text(s + "...", font) > width) s.pop_back();
  return s + "...";
}

// A fixed, evenly spread horizontal offset per dot (no random jitter: the same data give the
// same picture), so equal values side by side stay visible.
double dot_offset(size_t i, size_t n, double half_width) {
  if (n <= 1) return 0;
  return half_width * (2.0 * static_cast<double>(i) / static_cast<double>(n - 1) - 1.0);
}

// The name under column g when the labels are keyed: A..Z, then 27, 28, ...
std::string column_key(size_t g) { return g < 26 ? std::string(1, static_cast<char>('A' + g)) : std::to_string(g + 1); }

// The legend: the lettered labels when some do not fit under their column (`keyed`), then the
// reference and bound lines.
std::vector<LegendItem> strip_legend(const StripPlot& plot, bool keyed) {
  // Past kMaxKeyed entries the legend says how many it leaves to the tables.
  constexpr size_t kMaxKeyed = 40;
  const size_t n = plot.groups.size();
  std::vector<LegendItem> legend;
  if (keyed) {
    for (size_t g = 0; g < std::min(n, kMaxKeyed); ++g)
      legend.push_back({column_key(g) + ": " + plot.groups[g].label, class_color(static_cast<int>(g)), Marker::Dot});
    if (n > kMaxKeyed) legend.push_back({"and " + std::to_string(n - kMaxKeyed) + " more groups", kText, Marker::Dot});
  }
  if (plot.reference) legend.push_back({plot.reference_label.empty() ? "reference" : plot.reference_label, kText, Marker::Line});
  if (plot.bound) legend.push_back({plot.bound_label.empty() ? "bound" : plot.bound_label, kText, Marker::DashedLine});
  return legend;
}

// The value axis: every plottable value, the reference and the bound inside, on nice ticks.
struct ValueAxis {
  double lo = 0, hi = 1;
  std::vector<double> ticks;
};

ValueAxis value_axis(const StripPlot& plot) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto include = [&](double v) {
    if (plottable(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  };
  for (const auto& g : plot.groups)
    for (double v : g.values) include(v);
  if (plot.reference) include(*plot.reference);
  if (plot.bound) include(*plot.bound);
  if (!(lo <= hi)) lo = 0, hi = 1;
  if (lo >= 0 && lo < 0.5 * hi) lo = 0;  // errors and distances: an axis from 0 shows ratios honestly
  if (hi - lo <= std::abs(hi) * 1e-12) {
    const double w = std::max(0.5, std::abs(lo) * 1e-3);
    lo -= w, hi += w;
  }
  const std::vector<double> first = nice_ticks(lo, hi, 5);
  const double step = first.size() >= 2 ? first[1] - first[0] : hi - lo;
  lo = std::floor(lo / step + 1e-9) * step;
  hi = std::ceil(hi / step - 1e-9) * step;
  if (hi <= lo) hi = lo + step;
  return {lo, hi, nice_ticks(lo, hi, 5)};
}

// One group's column centred on cx: whiskers min to max, the box q1 to q3, the median, a dot per
// sample, and under the axis at `bottom` its label (or key) and its count.
void draw_group(cairo_t* cr, const StripGroup& group, size_t g, double cx, double col, double bottom, bool keyed,
                const std::function<double(double)>& Y) {
  std::vector<double> finite;
  for (double v : group.values)
    if (plottable(v)) finite.push_back(v);
  const Summary s = summarize(finite);
  const Rgb c = class_color(static_cast<int>(g));
  const double bw = std::min(col * 0.5, 60.0);
  if (s.count > 0) {
    set_color(cr, kAxis);  // whiskers
    cairo_move_to(cr, cx, Y(s.min));
    cairo_line_to(cr, cx, Y(s.q1));
    cairo_move_to(cr, cx, Y(s.q3));
    cairo_line_to(cr, cx, Y(s.max));
    cairo_stroke(cr);
    set_color(cr, c, 0.18);  // the box from q1 to q3
    cairo_rectangle(cr, cx - bw / 2, Y(s.q3), bw, std::max(1.0, Y(s.q1) - Y(s.q3)));
    cairo_fill_preserve(cr);
    set_color(cr, c, 0.9);
    cairo_stroke(cr);
    cairo_set_line_width(cr, 2.5);  // the median
    cairo_move_to(cr, cx - bw / 2, Y(s.median));
    cairo_line_to(cr, cx + bw / 2, Y(s.median));
    cairo_stroke(cr);
    cairo_set_line_width(cr, 1);
  }
  for (size_t i = 0; i < finite.size(); ++i) {  // one dot per sample, over the box
    const double x = cx + dot_offset(i, finite.size(), bw * 0.35);
    cairo_arc(cr, x, Y(finite[i]), 3.5, 0, 2 * M_PI);
    set_color(cr, c);
    cairo_fill_preserve(cr);
    set_color(cr, {1, 1, 1});
    cairo_stroke(cr);
  }
  set_color(cr, kText);
  const std::string label = keyed ? column_key(g) : group.label;
  draw_text(cr, label, cx, bottom + 5, kChartTickFont, HAlign::Center, VAlign::Top);
  std::string count = "n = " + std::to_string(s.count);
  if (group.values.size() > s.count) count += " (" + std::to_string(group.values.size() - s.count) + " not finite)";
  draw_text(cr, fitted(count, col - 6, kChartTickFont * 0.9), cx, bottom + 5 + kChartTickFont * 1.4, kChartTickFont * 0.9, HAlign::Center,
            VAlign::Top);
}

// A horizontal line across the plot at value v (the reference solid, the bound dashed).
void draw_level(cairo_t* cr, double v, bool dashed, double left, double right, const std::function<double(double)>& Y) {
  if (!plottable(v)) return;
  cairo_save(cr);
  set_color(cr, kText, 0.8);
  cairo_set_line_width(cr, 1.2);
  if (dashed) {
    const double dash[] = {5, 4};
    cairo_set_dash(cr, dash, 2, 0);
  }
  cairo_move_to(cr, left, Y(v));
  cairo_line_to(cr, right, Y(v));
  cairo_stroke(cr);
  cairo_restore(cr);
}

}  // namespace

void plot_strips(const std::string& path, const StripPlot& plot, int height_px) {
  const size_t n = plot.groups.size();
  // Columns narrow past ~135 groups so the image stays within render's side limit (a gather
  // of many configurations draws thin columns instead of failing).
  const double column = std::min(kColumn, (kMaxImageSide - 2 * kChartPad - 70) / static_cast<double>(std::max<size_t>(n, 1)));
  const double columns_width = std::max(360.0, 2 * kChartPad + 70 + column * static_cast<double>(std::max<size_t>(n, 1)));
  // Labels that do not fit under their column are lettered and listed whole in the legend: a
  // sweep's labels differ at their end ("... [separation=0]", "... [separation=1]"), which an
  // ellipsis would cut off. The image widens to the title and the longest entry (up to
  // kMaxWidth).
  constexpr double kMaxWidth = 1400;
  const bool keyed = std::any_of(plot.groups.begin(), plot.groups.end(), [&](const StripGroup& g) {
    return measure_text(g.label, kChartTickFont) > column - 6;
  });
  std::vector<LegendItem> legend = strip_legend(plot, keyed);
  double wanted = measure_text(plot.title, kChartTitleFont, true) + 2 * kChartPad + 80;
  for (const auto& item : legend) wanted = std::max(wanted, measure_text(item.label, kChartLegendFont) + 2 * kChartPad + 120);
  const double width = std::max(columns_width, std::min(kMaxWidth, wanted));
  for (auto& item : legend) item.label = fitted(item.label, width - 2 * kChartPad - 110, kChartLegendFont);
  // The legend's rows add to the height, so the plot keeps its own.
  const double legend_rows = legend.empty() ? 0 : legend_height(legend, width - 2 * kChartPad - 80, kChartLegendFont);
  height_px += static_cast<int>(std::max(0.0, legend_rows - kChartLegendFont * 2));
  const ValueAxis axis = value_axis(plot);
  const double lo = axis.lo, hi = axis.hi;
  const std::vector<double>& yt = axis.ticks;

  render_to_file(path, static_cast<int>(std::ceil(width)), height_px, [&](cairo_t* cr) {
    double ytw = 0;
    for (double t : yt) ytw = std::max(ytw, measure_text(tick_label(t), kChartTickFont));
    const double left = kChartPad + (plot.ylabel.empty() ? 0 : kChartLabelFont * 1.5) + ytw + 8;
    const double right = width - kChartPad;
    const double top = plot.title.empty() ? kChartPad : kChartTitleFont * 2.2;
    const double leg_h = legend.empty() ? 0 : legend_height(legend, right - left, kChartLegendFont);
    const double bottom = height_px - kChartPad - leg_h - 2 * kChartTickFont * 1.5;
    const double pw = right - left, ph = bottom - top;
    if (pw < 10 || ph < 10) return;
    const std::function<double(double)> Y = [&](double v) { return bottom - (std::clamp(v, lo, hi) - lo) / (hi - lo) * ph; };
    const double col = pw / static_cast<double>(std::max<size_t>(n, 1));  // the column as drawn

    set_color(cr, kText);
    if (!plot.title.empty()) draw_text(cr, plot.title, left, kChartTitleFont * 1.5, kChartTitleFont, HAlign::Left, VAlign::Baseline, true);
    if (!plot.ylabel.empty())
      draw_text(cr, plot.ylabel, kChartPad, top + ph / 2, kChartLabelFont, HAlign::Center, VAlign::Top, false, -M_PI / 2);
    draw_y_grid(cr, yt, left, right, Y);
    for (size_t g = 0; g < n; ++g) draw_group(cr, plot.groups[g], g, left + col * (static_cast<double>(g) + 0.5), col, bottom, keyed, Y);
    if (plot.reference) draw_level(cr, *plot.reference, false, left, right, Y);
    if (plot.bound) draw_level(cr, *plot.bound, true, left, right, Y);

    set_color(cr, kAxis);
    cairo_rectangle(cr, std::round(left) + 0.5, std::round(top) + 0.5, std::round(pw), std::round(ph));
    cairo_stroke(cr);
    if (!legend.empty()) draw_legend(cr, legend, left, height_px - kChartPad - leg_h, right - left, kChartLegendFont);
  });
}

}  // namespace ppsynth
