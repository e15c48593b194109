#pragma once
// Internal building blocks shared by the point, curve and image plots (not a public API for
// other modules): a measuring context for layout before the surface exists, "nice" tick
// positions, number formatting for tick labels, and a wrapping legend of color swatches.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <cairo.h>

#include "core/render/palette.hpp"

namespace ppsynth::render {

// Text widths before the output surface exists (a 1x1 image surface context).
double measure_text(const std::string& text, double size_px, bool bold = false);

// About `target` evenly spaced ticks covering [lo, hi] at 1/2/5 x 10^k steps, inside it.
std::vector<double> nice_ticks(double lo, double hi, int target = 5);
// Ticks at 10^k inside [lo, hi] (lo > 0), plus 2x/5x when fewer than three decades.
std::vector<double> log_ticks(double lo, double hi);
// Short label: "0", "0.25", "1e-05", "1000".
std::string tick_label(double v);

enum class Marker { Dot, Line, DashedLine, Disk };
struct LegendItem {
  std::string label;
  Rgb color;
  Marker marker = Marker::Dot;
};
// Height of a legend laid out left to right, wrapping at `width`.
double legend_height(const std::vector<LegendItem>& items, double width, double font_px = 12);
// Draws it with the top-left corner at (x, y).
void draw_legend(cairo_t* cr, const std::vector<LegendItem>& items, double x, double y,
                 double width, double font_px = 12);

inline void set_color(cairo_t* cr, const Rgb& c, double alpha = 1.0) {
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

// The look of the charts with axes (plot_curves, plot_strips): padding and font sizes in px.
inline constexpr double kChartPad = 12;
inline constexpr double kChartTitleFont = 14.5;
inline constexpr double kChartLabelFont = 12.5;
inline constexpr double kChartTickFont = 11;
inline constexpr double kChartLegendFont = 12;

// Values beyond +-kMaxPlotValue are left out like NaN: their differences would overflow the
// axis arithmetic and hand cairo non-finite coordinates.
inline constexpr double kMaxPlotValue = 1e150;
inline bool plottable(double v) { return std::isfinite(v) && std::abs(v) <= kMaxPlotValue; }

// Horizontal grid lines at the y `ticks` from `left` to `right`, labeled left of `left`;
// `y_of` maps a value to its pixel row.
void draw_y_grid(cairo_t* cr, const std::vector<double>& ticks, double left, double right,
                 const std::function<double(double)>& y_of);

// Colors of text and lines used everywhere (dark gray text, light grid).
inline constexpr Rgb kText{0.15, 0.15, 0.15};
inline constexpr Rgb kAxis{0.35, 0.35, 0.35};
inline constexpr Rgb kGrid{0.90, 0.90, 0.90};

}  // namespace ppsynth::render
