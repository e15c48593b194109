#pragma once
// The numbers of one evaluation of the Gabor maps (models/gabor_feature_maps.hpp), shared by
// its two implementations, the CPU kernel (gabor_feature_maps.cpp) and the tensor operations
// that run on any device (gabor_maps_tensor_ops.hpp), and their round trip through an
// autograd context, so that a graph owns the parameters its backward needs.
#include <torch/torch.h>

#include <cstdint>
#include <vector>

#include "models/gabor_channels.hpp"

namespace ppsynth {

inline constexpr double kTwoPi = 6.283185307179586;

// Filled from GaborMapsOptions by forward() and from the autograd context by backward(): no
// defaults of its own (those are GaborMapsOptions').
struct MapsParams {
  double sigma = 0;        // output-grid sigma (already divided by u)
  double frequency = 0;    // f = base_frequency u
  int k = 0;
  int divisor = 0;  // each grid position's sum over its k neighbors is divided by this
  bool periodic = false;
  std::vector<GaborChannel> channels;

  void save(torch::autograd::AutogradContext* ctx) const {
    std::vector<int64_t> codes;
    for (auto& c : channels) codes.push_back((c.freq + 1) * 1000 + (c.weight + 1));
    ctx->saved_data["sigma"] = sigma;
    ctx->saved_data["frequency"] = frequency;
    ctx->saved_data["k"] = static_cast<int64_t>(k);
    ctx->saved_data["divisor"] = static_cast<int64_t>(divisor);
    ctx->saved_data["periodic"] = periodic;
    ctx->saved_data["channels"] = codes;
  }
  static MapsParams load(torch::autograd::AutogradContext* ctx) {
    MapsParams mp;
    mp.sigma = ctx->saved_data["sigma"].toDouble();
    mp.frequency = ctx->saved_data["frequency"].toDouble();
    mp.k = static_cast<int>(ctx->saved_data["k"].toInt());
    mp.divisor = static_cast<int>(ctx->saved_data["divisor"].toInt());
    mp.periodic = ctx->saved_data["periodic"].toBool();
    for (int64_t code : ctx->saved_data["channels"].toIntVector())
      mp.channels.push_back({static_cast<int>(code / 1000) - 1, static_cast<int>(code % 1000) - 1});
    return mp;
  }
};

// The maps (C x G, G grid positions) of `points` (N x 2, may require grad) with weights
// (N x A, or 0 x 0 for none) at `grid` (G x 2) from the neighbor indices `idx` (G x k),
// differentiable in the points through an analytic backward.
// The CPU kernel: CPU tensors only (gabor_feature_maps.cpp).
torch::Tensor gabor_maps_cpu_kernel(const torch::Tensor& points, const torch::Tensor& weights, const torch::Tensor& grid,
                                    const torch::Tensor& idx, const MapsParams& params);
// LibTorch operations on the tensors' own device (gabor_maps_tensor_ops.cpp).
torch::Tensor gabor_maps_tensor_ops(const torch::Tensor& points, const torch::Tensor& weights, const torch::Tensor& grid,
                                    const torch::Tensor& idx, const MapsParams& params);

}  // namespace ppsynth
