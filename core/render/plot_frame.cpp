#include "core/render/plot_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/render/canvas.hpp"

namespace ppsynth::render {

double measure_text(const std::string& text, double size_px, bool bold) {
  static cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
  cairo_t* cr = cairo_create(s);
  const double w = text_width(cr, text, size_px, bold);
  cairo_destroy(cr);
  return w;
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> out;
  if (!(std::isfinite(lo) && std::isfinite(hi)) || hi <= lo) {
    if (std::isfinite(lo)) out.push_back(lo);
    return out;
  }
  const double raw = (hi - lo) / std::max(1, target);
  if (!std::isfinite(raw) || !(raw > 0)) {  // [-1e308, 1e308]: the width overflows
    out.push_back(lo);
    out.push_back(hi);
    return out;
  }
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  if (!std::isfinite(step) || !(step > 0)) {
    out.push_back(lo);
    return out;
  }
  const double eps = step * 1e-9;
  // t_k = first + k step (not t += step: below the precision of lo, e.g. [1e20, 1e20 + 1 ulp],
  // t += step leaves t unchanged and the loop never ended); at most kMaxTicks, each one new.
  const double first = std::ceil((lo - eps) / step) * step;
  constexpr int kMaxTicks = 64;
  for (int k = 0; k < kMaxTicks; ++k) {
    const double t = first + k * step;
    if (!(t <= hi + eps)) break;
    if (!out.empty() && !(t > out.back())) continue;
    out.push_back(std::fabs(t) < eps ? 0.0 : t);
  }
  return out;
}

std::vector<double> log_ticks(double lo, double hi) {
  std::vector<double> out;
  if (!(lo > 0) || !(hi > lo)) return out;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return out;
  const int k0 = static_cast<int>(std::floor(std::log10(lo))), k1 = static_cast<int>(std::ceil(std::log10(hi)));
  const bool fine = (k1 - k0) < 3;
  const int stride = std::max(1, (k1 - k0) / 6);  // at most ~7 decade labels
  for (int k = k0; k <= k1; ++k) {
    for (double m : {1.0, 2.0, 5.0}) {
      if (m != 1.0 && !fine) continue;
      if (m == 1.0 && !fine && (k - k0) % stride) continue;
      const double v = m * std::pow(10.0, k);
      if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) out.push_back(v);
    }
  }
  return out;
}

std::string tick_label(double v) {
  char buf[32];
  if (v == 0) return "0";
  const double a = std::fabs(v);
  if (a >= 1e-3 && a < 1e5)
    std::snprintf(buf, sizeof buf, "%.4g", v);
  else
    std::snprintf(buf, sizeof buf, "%.0e", v);
  return buf;
}

namespace {
constexpr double kSwatch = 22;  // swatch width (px) incl. gap before the label
constexpr double kItemGap = 16;
double item_width(const LegendItem& it, double font_px) { return kSwatch + measure_text(it.label, font_px) + kItemGap; }
}  // namespace

double legend_height(const std::vector<LegendItem>& items, double width, double font_px) {
  if (items.empty()) return 0;
  const double line = font_px * 1.6;
  double x = 0;
  int lines = 1;
  for (const auto& it : items) {
    const double w = item_width(it, font_px);
    if (x > 0 && x + w > width) {
      ++lines;
      x = 0;
    }
    x += w;
  }
  return lines * line;
}

void draw_legend(cairo_t* cr, const std::vector<LegendItem>& items, double x0, double y0, double width,
                 double font_px) {
  const double line = font_px * 1.6;
  double x = 0, y = 0;
  for (const auto& it : items) {
    const double w = item_width(it, font_px);
    if (x > 0 && x + w > width) {
      x = 0;
      y += line;
    }
    const double cy = y0 + y + line / 2, cx = x0 + x;
    cairo_save(cr);
    cairo_new_path(cr);
    switch (it.marker) {
      case Marker::Dot:
        set_color(cr, it.color);
        cairo_arc(cr, cx + 7, cy, 4.5, 0, 2 * M_PI);
        cairo_fill(cr);
        break;
      case Marker::Disk:
        set_color(cr, it.color, 0.35);
        cairo_arc(cr, cx + 7, cy, 6, 0, 2 * M_PI);
        cairo_fill_preserve(cr);
        set_color(cr, it.color);
        cairo_set_line_width(cr, 1.2);
        cairo_stroke(cr);
        break;
      case Marker::Line:
      case Marker::DashedLine: {
        set_color(cr, it.color);
        cairo_set_line_width(cr, 2);
        if (it.marker == Marker::DashedLine) {
          const double d[] = {4, 3};
          cairo_set_dash(cr, d, 2, 0);
        }
        cairo_move_to(cr, cx, cy);
        cairo_line_to(cr, cx + 16, cy);
        cairo_stroke(cr);
        break;
      }
    }
    set_color(cr, kText);
    draw_text(cr, it.label, cx + kSwatch, cy, font_px, HAlign::Left, VAlign::Middle);
    cairo_restore(cr);
    x += w;
  }
}

void draw_y_grid(cairo_t* cr, const std::vector<double>& ticks, double left, double right,
                 const std::function<double(double)>& y_of) {
  cairo_set_line_width(cr, 1);
  for (double t : ticks) {
    set_color(cr, kGrid);
    cairo_move_to(cr, left, std::round(y_of(t)) + 0.5);
    cairo_line_to(cr, right, std::round(y_of(t)) + 0.5);
    cairo_stroke(cr);
    set_color(cr, kText);
    draw_text(cr, tick_label(t), left - 6, y_of(t), kChartTickFont, HAlign::Right, VAlign::Middle);
  }
}

}  // namespace ppsynth::render
