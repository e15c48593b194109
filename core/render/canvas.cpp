#include "core/render/canvas.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <algorithm>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace ppsynth::render {

namespace {

void check(cairo_status_t st, const std::string& path, const char* what) {
  if (st != CAIRO_STATUS_SUCCESS)
    throw file_error(path, 0, std::string(what) + ": " + cairo_status_to_string(st));
}

}  // namespace

void render_to_file(const std::string& path, int width, int height,
                    const std::function<void(cairo_t*)>& draw) {
  if (width <= 0 || height <= 0)
    throw file_error(path, 0, "image size must be positive (got " + std::to_string(width) + "x" +
                                  std::to_string(height) + ")");
  if (!image_size_ok(width, height))
    throw file_error(path, 0, "image of " + std::to_string(width) + " x " + std::to_string(height) +
                                  " px is beyond the limit of " + std::to_string(kMaxImageSide) + " px a side and " +
                                  std::to_string(static_cast<long>(kMaxImagePixels / 1e6)) + " megapixels");
  const ImageKind kind = image_kind_for(path);  // before any file is touched
  write_via_temp(path, [&](const std::string& tmp) {
    cairo_surface_t* surface = nullptr;
    switch (kind) {
      case ImageKind::Png: surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height); break;
      case ImageKind::Svg: surface = cairo_svg_surface_create(tmp.c_str(), width, height); break;
      case ImageKind::Pdf: surface = cairo_pdf_surface_create(tmp.c_str(), width, height); break;
    }
    // RAII for the surface and context so an exception in draw() releases both.
    struct Guard {
      cairo_surface_t* s;
      cairo_t* cr = nullptr;
      ~Guard() {
        if (cr) cairo_destroy(cr);
        cairo_surface_destroy(s);
      }
    } g{surface};
    check(cairo_surface_status(surface), path, "cannot create image surface");
    g.cr = cairo_create(surface);
    cairo_t* cr = g.cr;
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    draw(cr);
    check(cairo_status(cr), path, "drawing failed");
    cairo_surface_flush(surface);
    if (kind == ImageKind::Png) {
      check(cairo_surface_write_to_png(surface, tmp.c_str()), path, "cannot write PNG");
    } else {
      cairo_destroy(cr);
      g.cr = nullptr;
      cairo_surface_finish(surface);
      check(cairo_surface_status(surface), path, "cannot write image");
    }
  });
}

namespace {

// The one label font (sans-serif, regular or bold) set on `cr`; returns the text's extents in it.
cairo_text_extents_t select_font(cairo_t* cr, const std::string& text, double size_px, bool bold) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size_px);
  cairo_text_extents_t te;
  cairo_text_extents(cr, text.c_str(), &te);
  return te;
}

}  // namespace

void draw_text(cairo_t* cr, const std::string& text, double x, double y, double size_px, HAlign h,
               VAlign v, bool bold, double angle_rad) {
  if (text.empty()) return;
  cairo_save(cr);
  const cairo_text_extents_t te = select_font(cr, text, size_px, bold);
  cairo_font_extents_t fe;
  cairo_font_extents(cr, &fe);
  double dx = 0, dy = 0;
  switch (h) {
    case HAlign::Left: dx = 0; break;
    case HAlign::Center: dx = -te.x_advance / 2; break;
    case HAlign::Right: dx = -te.x_advance; break;
  }
  // Use the font's ascent/descent (not the ink box) so labels line up regardless of glyphs.
  switch (v) {
    case VAlign::Top: dy = fe.ascent; break;
    case VAlign::Middle: dy = (fe.ascent - fe.descent) / 2; break;
    case VAlign::Baseline: dy = 0; break;
    case VAlign::Bottom: dy = -fe.descent; break;
  }
  cairo_translate(cr, x, y);
  cairo_rotate(cr, angle_rad);
  cairo_move_to(cr, dx, dy);
  cairo_show_text(cr, text.c_str());
  cairo_new_path(cr);  // show_text leaves a current point; the path is not part of save/restore
  cairo_restore(cr);
}

double text_width(cairo_t* cr, const std::string& text, double size_px, bool bold) {
  cairo_save(cr);
  const cairo_text_extents_t te = select_font(cr, text, size_px, bold);
  cairo_restore(cr);
  return te.x_advance;
}

void paint_image_nearest(cairo_t* cr, cairo_surface_t* image, double x, double y, double w, double h, double scale) {
  cairo_save(cr);
  cairo_rectangle(cr, x, y, w, h);
  cairo_clip(cr);
  cairo_translate(cr, x, y);
  cairo_scale(cr, scale, scale);
  cairo_set_source_surface(cr, image, 0, 0);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(image);
}

}  // namespace ppsynth::render
