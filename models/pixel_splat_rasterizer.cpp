// "pixel_splat": points splatted into a rows x res image with bilinear weights, so the image
// is differentiable in the positions (Fig. 12c: random filters on pixelized points, no
// Gabor maps). One channel per weight column (1 without attributes); the pixel value is
// the summed weight, i.e. a point density.
#include "core/config/defaults_catalog.hpp"
#include "models/rasterizer.hpp"

namespace ppsynth {
namespace {

class PixelSplatRasterizer : public Rasterizer {
 public:
  PixelSplatRasterizer(int res, int rows) : res_(res), rows_(rows > 0 ? rows : res) {}

  torch::Tensor forward(const torch::Tensor& points, const torch::Tensor& weights, double,
                        const torch::Tensor&) override {
    const int64_t R = res_, rows = rows_;
    // Pixel centers at the Gabor grid positions: u = (x - b) / (1 - 2b) * (R - 1); rows at the
    // columns' spacing (models/feature_grid.hpp).
    const double b = 1.0 / (R + 1);
    auto uv = (points - b) / (1.0 - 2.0 * b) * static_cast<double>(R - 1);
    auto uv0 = torch::floor(uv.detach());
    auto frac = uv - uv0;  // carries the gradient
    auto i0 = uv0.to(torch::kLong);
    const int C = weights.defined() ? static_cast<int>(weights.size(1)) : 1;
    std::vector<torch::Tensor> img(C, torch::zeros({rows * R}, points.options()));
    for (int dy = 0; dy <= 1; ++dy)
      for (int dx = 0; dx <= 1; ++dx) {
        auto wx = dx ? frac.select(1, 0) : 1 - frac.select(1, 0);
        auto wy = dy ? frac.select(1, 1) : 1 - frac.select(1, 1);
        auto col = i0.select(1, 0) + dx, row = i0.select(1, 1) + dy;
        auto inside = (col >= 0) & (col < R) & (row >= 0) & (row < rows);
        auto flat = (row.clamp(0, rows - 1) * R + col.clamp(0, R - 1));
        auto w = wx * wy * inside.to(points.scalar_type());
        for (int c = 0; c < C; ++c) {
          auto wc = weights.defined() ? w * weights.select(1, c) : w;
          img[c] = img[c].index_add(0, flat, wc);  // out-of-place: autograd-friendly
        }
      }
    return torch::stack(img).view({1, C, rows, R});
  }
  int channels(int A) const override { return A == 0 ? 1 : A; }
  bool uses_jitter() const override { return false; }

 private:
  int res_, rows_;
};

}  // namespace
}  // namespace ppsynth

namespace ppsynth {
namespace {
struct PixelSplatOptions {  // none: the grid is the method's (RasterizerArgs)
  static const ParamTable<PixelSplatOptions>& params() {
    static const ParamTable<PixelSplatOptions> t("method.rasterizer", {});
    return t;
  }
};
}  // namespace
}  // namespace ppsynth

PPSYNTH_REGISTER_PARAMS(ppsynth::RasterizerRegistry, "rasterizer", "pixel_splat", ppsynth::PixelSplatOptions::params(),
                        "bilinear splat of points into pixels (Fig. 12c: random filters only)",
                        [](const ppsynth::PixelSplatOptions&, const std::string&,
                           ppsynth::RasterizerArgs a) -> std::unique_ptr<ppsynth::Rasterizer> {
                          return std::make_unique<ppsynth::PixelSplatRasterizer>(a.res, a.rows);
                        })
