#pragma once
// What a figure's file may be, without drawing it (no cairo): the format its extension asks
// for and the size limits every figure keeps. A build without cairo (PPSYNTH_WITH_CAIRO=OFF)
// has these and leaves the drawing out (core/render/without_cairo/plots_left_out.cpp).
#include <string>

namespace ppsynth::render {

enum class ImageKind { Png, Svg, Pdf };

// Size limits of every figure: cairo's image surfaces stop at 32767 px a side, and an ARGB
// raster of W x H px needs 4 W H bytes (kMaxImagePixels: 320 MB, what `ppsynth plot --size
// 8000` needs). Vector files use the same limits so a figure looks the same in every format.
inline constexpr int kMaxImageSide = 16384;
inline constexpr double kMaxImagePixels = 80.0e6;
// True when a width x height figure is within both limits.
bool image_size_ok(double width, double height);

// Extension (case-insensitive) -> kind. Unknown or missing extension => InputError naming
// the path and the accepted extensions.
ImageKind image_kind_for(const std::string& path);

}  // namespace ppsynth::render
