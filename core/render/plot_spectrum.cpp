#include "core/render/plot_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/error.hpp"
#include "core/metrics/summary_stats.hpp"
#include "core/render/canvas.hpp"
#include "core/render/palette.hpp"
#include "core/render/plot_frame.hpp"

namespace ppsynth {
namespace {

using namespace render;

constexpr double kLeft = 64, kTop = 34, kBottom = 46, kBarGap = 14, kBarW = 16, kRight = 64;
constexpr double kDynamicRange = 1e-6;  // lowest color: at least this fraction of the maximum
constexpr Rgb kDcColor{0.6, 0.6, 0.6};

struct LogRange {
  double lo = 0, hi = 1;  // log10 of the power
  double t(double p) const { return p > 0 ? std::clamp((std::log10(p) - lo) / (hi - lo), 0.0, 1.0) : 0.0; }
};

LogRange range_of(const Periodogram& p) {
  std::vector<double> positive;
  double mx = 0;
  for (double v : p.power)
    if (v > 0 && std::isfinite(v)) positive.push_back(v), mx = std::max(mx, v);
  LogRange r;
  if (positive.empty()) return r;
  const double lo = std::max(quantile(positive, 0.01), mx * kDynamicRange);
  r.hi = std::log10(mx);
  r.lo = std::log10(lo);
  if (r.hi - r.lo < 1e-9) r.lo = r.hi - 1;  // a flat spectrum still gets a ramp
  return r;
}

// The heat map as an RGB image, row 0 = highest fy (y up).
cairo_surface_t* heat_image(const Periodogram& p, const LogRange& r) {
  const int S = p.side();
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, S, S);
  cairo_surface_flush(s);
  unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  auto u8 = [](double v) { return static_cast<uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  for (int row = 0; row < S; ++row) {
    auto* line = reinterpret_cast<uint32_t*>(data + row * stride);
    const int ky = p.F - row;
    for (int col = 0; col < S; ++col) {
      const int kx = col - p.F;
      const Rgb c = (kx == 0 && ky == 0) ? kDcColor : viridis(r.t(p.at(kx, ky)));
      line[col] = (u8(c.r) << 16) | (u8(c.g) << 8) | u8(c.b);
    }
  }
  cairo_surface_mark_dirty(s);
  return s;
}

}  // namespace

void plot_spectrum(const std::string& path, const Periodogram& p, const std::string& title, int frame_px) {
  render::image_kind_for(path);  // a bad extension fails before any work
  if (frame_px < 64) throw InputError("plot " + path + ": the spectrum frame must be at least 64 px");
  if (p.F < 1 || p.power.size() != static_cast<size_t>(p.side()) * p.side())
    throw InputError("plot " + path + ": the periodogram has " + std::to_string(p.power.size()) + " values for F = " +
                     std::to_string(p.F));
  const LogRange range = range_of(p);
  const double side = frame_px, fmax = p.F * p.step;
  const double width = kLeft + side + kBarGap + kBarW + kRight, height = kTop + side + kBottom;
  render::render_to_file(path, static_cast<int>(std::ceil(width)), static_cast<int>(std::ceil(height)), [&](cairo_t* cr) {
    const double fx0 = kLeft, fy0 = kTop;
    set_color(cr, kText);
    draw_text(cr, title.empty() ? "power spectrum" : title, fx0, kTop - 12, 14, HAlign::Left, VAlign::Baseline, true);
    // Heat map: one square per frequency (nearest neighbor), centered on its frequency.
    const double scale = side / p.side();
    paint_image_nearest(cr, heat_image(p, range), fx0, fy0, side, side, scale);
    // Axes: frequency f maps to the center of its square.
    auto X = [&](double f) { return fx0 + (f / p.step + p.F + 0.5) * scale; };
    auto Y = [&](double f) { return fy0 + (p.F - f / p.step + 0.5) * scale; };
    cairo_set_line_width(cr, 0.8);
    for (double t : nice_ticks(-fmax, fmax, 6)) {
      set_color(cr, kAxis);
      cairo_move_to(cr, X(t), fy0 + side);
      cairo_line_to(cr, X(t), fy0 + side + 4);
      cairo_move_to(cr, fx0, Y(t));
      cairo_line_to(cr, fx0 - 4, Y(t));
      cairo_stroke(cr);
      set_color(cr, kText);
      draw_text(cr, tick_label(t), X(t), fy0 + side + 6, kChartTickFont, HAlign::Center, VAlign::Top);
      draw_text(cr, tick_label(t), fx0 - 6, Y(t), kChartTickFont, HAlign::Right, VAlign::Middle);
    }
    set_color(cr, kText);
    draw_text(cr, "fx (cycles per unit)", fx0 + side / 2, height - 8, kChartLabelFont, HAlign::Center, VAlign::Bottom);
    draw_text(cr, "fy (cycles per unit)", 14, fy0 + side / 2, kChartLabelFont, HAlign::Center, VAlign::Middle, false,
              -M_PI / 2);
    set_color(cr, kAxis);
    cairo_rectangle(cr, fx0, fy0, side, side);
    cairo_stroke(cr);
    // Color bar: log10 power, labeled at the decades inside the range.
    const double bx = fx0 + side + kBarGap;
    const int steps = 64;
    for (int i = 0; i < steps; ++i) {
      set_color(cr, viridis((i + 0.5) / steps));
      cairo_rectangle(cr, bx, fy0 + side * (1 - (i + 1.0) / steps), kBarW, side / steps + 0.5);
      cairo_fill(cr);
    }
    set_color(cr, kAxis);
    cairo_rectangle(cr, bx, fy0, kBarW, side);
    cairo_stroke(cr);
    for (double v : log_ticks(std::pow(10.0, range.lo), std::pow(10.0, range.hi))) {
      const double y = fy0 + side * (1 - (std::log10(v) - range.lo) / (range.hi - range.lo));
      set_color(cr, kText);
      draw_text(cr, tick_label(v), bx + kBarW + 4, y, kChartTickFont, HAlign::Left, VAlign::Middle);
    }
    draw_text(cr, "power", bx, fy0 - 6, kChartTickFont, HAlign::Left, VAlign::Baseline);
  });
}

}  // namespace ppsynth
