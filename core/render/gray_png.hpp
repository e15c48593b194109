#pragma once
// Writes one scalar image as an 8-bit gray PNG (cairo, atomic via a temp file): value
// lo -> black, hi -> white, clamped. Used by `ppsynth pptbf` for the single image (the
// grid of several images goes through core/render/image_grid.hpp).
#include <string>

#include "core/render/image_grid.hpp"

namespace ppsynth {

// lo >= hi: the image's own min/max (a constant image renders black).
void write_gray_png(const std::string& path, const GrayImage& img, double lo = 0, double hi = 0);

}  // namespace ppsynth
