#include "core/render/gray_png.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <cairo.h>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace ppsynth {

void write_gray_png(const std::string& path, const GrayImage& img, double lo, double hi) {
  if (img.width <= 0 || img.height <= 0 || img.pixels.size() != static_cast<size_t>(img.width) * img.height)
    throw InputError(path + ": image size does not match its pixel count");
  if (lo >= hi) {
    auto [mn, mx] = std::minmax_element(img.pixels.begin(), img.pixels.end());
    lo = *mn;
    hi = *mx;
  }
  const double scale = hi > lo ? 255.0 / (hi - lo) : 0.0;
  cairo_surface_t* surf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, img.width, img.height);
  cairo_surface_flush(surf);
  unsigned char* data = cairo_image_surface_get_data(surf);
  const int stride = cairo_image_surface_get_stride(surf);
  for (int r = 0; r < img.height; ++r) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<size_t>(r) * stride);
    for (int c = 0; c < img.width; ++c) {
      const double v = img.pixels[static_cast<size_t>(r) * img.width + c];
      const auto g = static_cast<std::uint32_t>(std::clamp(std::isfinite(v) ? (v - lo) * scale : 0.0, 0.0, 255.0));
      row[c] = (g << 16) | (g << 8) | g;
    }
  }
  cairo_surface_mark_dirty(surf);
  try {
    write_via_temp(path, [&](const std::string& tmp) {
      if (cairo_surface_write_to_png(surf, tmp.c_str()) != CAIRO_STATUS_SUCCESS)
        throw InputError(path + ": cannot write PNG");
    });
  } catch (...) {
    cairo_surface_destroy(surf);
    throw;
  }
  cairo_surface_destroy(surf);
}

}  // namespace ppsynth
