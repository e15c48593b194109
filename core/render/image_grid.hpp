#pragma once
// A grid of scalar images (feature maps, 2-D spectra) with titles: the paper's Fig. 3
// (Gabor maps for varying frequency and sigma). Each image is scaled to fit a
// cell_px x cell_px cell (aspect kept, nearest-neighbor so pixels stay visible).
// Output format by extension: .png, .svg, .pdf; atomic writes.
#include <string>
#include <vector>

namespace ppsynth {

struct GrayImage {
  int width = 0, height = 0;
  std::vector<float> pixels;  // row-major, row 0 at the top; size width*height
  std::string title;
};

enum class ColorMap {
  Gray,       // min -> black, max -> white
  Viridis,    // min -> purple, max -> yellow
  Diverging,  // signed data: -max|v| blue, 0 white, +max|v| red
};

// normalize_each: each image uses its own min/max (or max|v| for Diverging); otherwise one
// range over all images so magnitudes are comparable. Constant images render mid-level.
// InputError if an image's pixel count does not match width*height or columns < 1.
void plot_image_grid(const std::string& path, const std::vector<GrayImage>& images, int columns,
                     int cell_px = 160, bool normalize_each = true,
                     ColorMap cmap = ColorMap::Gray);

}  // namespace ppsynth
