#include "core/render/image_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.hpp"

namespace ppsynth::render {

ImageKind image_kind_for(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".png") return ImageKind::Png;
  if (ext == ".svg") return ImageKind::Svg;
  if (ext == ".pdf") return ImageKind::Pdf;
  throw file_error(path, 0, "unknown image extension '" + ext + "' (use .png, .svg or .pdf)");
}

bool image_size_ok(double width, double height) {
  return width > 0 && height > 0 && width <= kMaxImageSide && height <= kMaxImageSide &&
         width * height <= kMaxImagePixels;
}

}  // namespace ppsynth::render
