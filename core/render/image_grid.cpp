#include "core/render/image_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/error.hpp"
#include "core/render/canvas.hpp"
#include "core/render/palette.hpp"
#include "core/render/plot_frame.hpp"

namespace ppsynth {
namespace {

using namespace render;

constexpr double kGap = 12, kTitleH = 20, kRangeH = 16;

struct MinMax {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
};

MinMax range_of(const GrayImage& im) {
  MinMax m;
  for (float v : im.pixels) m.add(v);
  return m;
}

Rgb map_value(double v, const MinMax& r, ColorMap cmap) {
  if (!std::isfinite(v)) return {1.0, 0.0, 1.0};  // magenta flags NaN/inf
  if (cmap == ColorMap::Diverging) {
    const double a = std::max(std::fabs(r.lo), std::fabs(r.hi));
    return diverging(a > 0 ? v / a : 0.0);
  }
  const double t = r.hi > r.lo ? (v - r.lo) / (r.hi - r.lo) : 0.5;
  return cmap == ColorMap::Viridis ? viridis(t) : gray(t);
}

// Paints `im` scaled (nearest neighbor) into the square cell at (x, y) of side `side`.
void draw_image(cairo_t* cr, const GrayImage& im, const MinMax& r, ColorMap cmap, double x, double y, double side) {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, im.width, im.height);
  cairo_surface_flush(s);
  unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int row = 0; row < im.height; ++row) {
    auto* line = reinterpret_cast<uint32_t*>(data + row * stride);
    for (int col = 0; col < im.width; ++col) {
      const Rgb c = map_value(im.pixels[static_cast<size_t>(row) * im.width + col], r, cmap);
      auto u8 = [](double v) { return static_cast<uint32_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
      line[col] = (u8(c.r) << 16) | (u8(c.g) << 8) | u8(c.b);
    }
  }
  cairo_surface_mark_dirty(s);
  const double scale = side / std::max(im.width, im.height);
  const double w = im.width * scale, h = im.height * scale;
  const double ox = x + (side - w) / 2, oy = y + (side - h) / 2;
  paint_image_nearest(cr, s, ox, oy, w, h, scale);
  cairo_save(cr);
  set_color(cr, kAxis);
  cairo_set_line_width(cr, 0.8);
  cairo_rectangle(cr, ox, oy, w, h);
  cairo_stroke(cr);
  cairo_restore(cr);
}

}  // namespace

void plot_image_grid(const std::string& path, const std::vector<GrayImage>& images, int columns, int cell_px,
                     bool normalize_each, ColorMap cmap) {
  render::image_kind_for(path);
  if (images.empty()) throw InputError("plot " + path + ": no images in the grid");
  if (columns < 1) throw InputError("plot " + path + ": columns must be >= 1 (got " + std::to_string(columns) + ")");
  if (cell_px < 16) throw InputError("plot " + path + ": cell size must be >= 16 px");
  MinMax global;
  for (size_t i = 0; i < images.size(); ++i) {
    const auto& im = images[i];
    if (im.width <= 0 || im.height <= 0 ||
        im.pixels.size() != static_cast<size_t>(im.width) * static_cast<size_t>(im.height))
      throw InputError("plot " + path + ": image " + std::to_string(i) + " ('" + im.title + "') has " +
                       std::to_string(im.pixels.size()) + " pixels for " + std::to_string(im.width) + "x" +
                       std::to_string(im.height));
    const MinMax m = range_of(im);
    global.add(m.lo), global.add(m.hi);
  }
  const int n = static_cast<int>(images.size());
  const int cols = std::min(columns, n), rows = (n + cols - 1) / cols;
  const double cw = cell_px + kGap, ch = kTitleH + cell_px + kRangeH + kGap;
  const double width = cols * cw + kGap, height = rows * ch + kGap;
  render::render_to_file(path, static_cast<int>(width), static_cast<int>(height), [&](cairo_t* cr) {
    for (int i = 0; i < n; ++i) {
      const auto& im = images[i];
      const double x = kGap + (i % cols) * cw, y = kGap + (i / cols) * ch;
      const MinMax r = normalize_each ? range_of(im) : global;
      set_color(cr, kText);
      // Long titles are shrunk to fit the cell.
      double fs = 12;
      while (fs > 7 && measure_text(im.title, fs) > cell_px) fs -= 0.5;
      draw_text(cr, im.title, x + cell_px / 2.0, y + kTitleH - 6, fs, HAlign::Center, VAlign::Baseline);
      draw_image(cr, im, r, cmap, x, y + kTitleH, cell_px);
      const MinMax own = range_of(im);
      set_color(cr, kAxis);
      const std::string range_text = own.lo <= own.hi ? "[" + tick_label(own.lo) + ", " + tick_label(own.hi) + "]" : "(no finite values)";
      draw_text(cr, range_text, x + cell_px / 2.0, y + kTitleH + cell_px + 3, 9.5, HAlign::Center, VAlign::Top);
    }
  });
}

}  // namespace ppsynth
