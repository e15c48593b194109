#pragma once
// Rasterizer: points (N x 2, may require grad) + per-point weights -> 1 x C x rows x res maps
// (rows = res: the square; a rectangle output's grid has rows of its own, models/feature_grid.hpp).
// The first stage of the pipeline. Implementations: "gabor" (the paper's Gabor maps, Eq. 5),
// "spatial" (gamma = 0 only: Fig. 11), "pixel_splat" (bilinear splat of points into
// pixels: the "random filters only" ablation, Fig. 12c).
#include <torch/torch.h>

#include "core/registry.hpp"

namespace ppsynth {

class Rasterizer : public torch::nn::Module {
 public:
  // sigma in exemplar units (ignored by pixel_splat); jitter: rows*res x 2 grid offsets or undefined.
  virtual torch::Tensor forward(const torch::Tensor& points, const torch::Tensor& weights, double sigma,
                                const torch::Tensor& jitter) = 0;
  // Channel count for A weight columns (sizes the first convolution).
  virtual int channels(int num_attributes) const = 0;
  // Whether grid jitter means anything for this rasterizer.
  virtual bool uses_jitter() const { return true; }
};

struct RasterizerArgs {
  int res = 128;        // grid positions per axis of THIS raster (output: u * exemplar res)
  double upscale = 1;   // u
  int k = 0;            // neighbors (Gabor): the method's "k", which defaults to GaborMapsOptions::k
  bool output = false;  // the raster of the synthesized points (not the exemplar's)
  int divisor = 0;      // Gabor: GaborMapsOptions::divisor (0: the neighbors summed)
  int rows = 0;         // grid positions along y at the columns' spacing; 0: res (the square)
};

using RasterizerRegistry = Registry<Rasterizer, RasterizerArgs>;

}  // namespace ppsynth
