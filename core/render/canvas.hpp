#pragma once
// One drawing surface per output file, chosen by the file extension: .png (raster, white
// background), .svg and .pdf (vector, sizes in points = "pixels" here). Every plot in
// core/render draws through render_to_file, so all plots share format choice, atomic
// writes (core/atomic_file.hpp write_via_temp; the temp name keeps the extension) and the
// text helpers below.
#include <functional>
#include <string>

#include <cairo.h>

#include "core/render/image_file.hpp"

namespace ppsynth::render {

// Creates a width x height surface of the kind `path` asks for, fills it white, calls
// `draw(cr)`, and writes the file atomically. Throws InputError if cairo reports an error
// (e.g. the folder does not exist) and, before anything is allocated, if the size is beyond
// the limits above (the message names both); no partial file is left behind.
void render_to_file(const std::string& path, int width, int height,
                    const std::function<void(cairo_t*)>& draw);

// --- text helpers (sans-serif "toy" font API; enough for labels and titles) -----------
enum class HAlign { Left, Center, Right };
enum class VAlign { Top, Middle, Baseline, Bottom };
// Draws `text` at (x, y) with the given size (px) and alignment in the current color.
void draw_text(cairo_t* cr, const std::string& text, double x, double y, double size_px,
               HAlign h = HAlign::Left, VAlign v = VAlign::Baseline, bool bold = false,
               double angle_rad = 0.0);
// Width in px of `text` at `size_px`.
double text_width(cairo_t* cr, const std::string& text, double size_px, bool bold = false);
// Paints `image` scaled by `scale` with its corner at (x, y), clipped to w x h, one block of
// pixels per image pixel (nearest neighbor: heat maps and rasters stay sharp). Takes
// ownership of `image`.
void paint_image_nearest(cairo_t* cr, cairo_surface_t* image, double x, double y, double w, double h, double scale);

}  // namespace ppsynth::render
