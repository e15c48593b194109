#pragma once
// RandomFilterNet: the paper's network of random filters (§4.1, method.md §3), never trained.
//
//   block1: conv kxk C->ch, [IN], [ReLU], conv kxk ch->ch, [IN], [ReLU]   -> F1 (full res)
//   block2: conv kxk ch->ch stride 2, [IN], [ReLU]                         -> F2 (1/2)
//   block3: conv kxk ch->ch stride 2, [IN], [ReLU]                         -> F3 (1/4)
//
// Defaults: RandomFilterNetOptions below, its config keys each declared once in its table
// (random_filter_net.cpp; the registry's defaults and bounds come from it): ch = 120, k = 7,
// instance norm (no affine, eps 1e-5) and ReLU on. Weights Glorot-uniform, biases
// PyTorch's default conv init, all drawn from the seed. `depth` adds/removes stride-2 blocks
// (depth 3 = the paper's 4 filtering layers).
#include "core/config/params.hpp"
#include "models/feature_net.hpp"

namespace ppsynth {

struct RandomFilterNetOptions {
  int in_channels = 10;
  int channels = 120;
  int kernel_size = 7;
  int depth = 3;  // number of blocks (features returned)
  bool instance_norm = true;
  bool relu = true;
  uint64_t seed = 95;
  // Arithmetic of the network: float32 (faithful) or bfloat16 (a speed knob where the CPU has
  // bf16 units; models/network_precision.hpp chooses from `precision`, the config's word).
  // Features return as float32, so the losses stay in float32. Weights are drawn in float32
  // from the seed either way.
  std::string precision = "float32";
  torch::Dtype dtype = torch::kFloat32;
  std::string precision_reason;  // how the precision was chosen (choices())
  // CPU fast path for float32 and bfloat16, batch 1 (the synthesis): channels-last
  // activations and an input-gradient-only backward (see random_filter_net.cpp). Same
  // features and gradients as the plain path within the precision's rounding
  // (tests/models/test_feature_nets.cpp); off = LibTorch's plain path.
  bool fast_cpu = true;

  // The config keys (channels, kernel_size, depth, instance_norm, relu, precision); the rest
  // are the caller's (in_channels, seed) or resolved (dtype).
  static const ParamTable<RandomFilterNetOptions>& params();
};

class RandomFilterNet : public FeatureNet {
 public:
  explicit RandomFilterNet(RandomFilterNetOptions options);
  Features forward(const torch::Tensor& maps) override;
  nlohmann::json choices() const override;
  const RandomFilterNetOptions& options() const { return opt_; }

 private:
  torch::Tensor activate(const torch::Tensor& x, bool fast) const;
  bool use_fast_path(const torch::Tensor& maps) const;
  RandomFilterNetOptions opt_;
  std::vector<torch::nn::Conv2d> convs_;
  // Fast path: each conv's filters channels-last, and transposed + flipped (the filters of
  // its input gradient, which is itself a convolution at stride 1).
  std::vector<torch::Tensor> w_cl_, w_grad_cl_;
  std::vector<int> block_end_;  // index of the last conv of each block
  std::vector<int64_t> strides_;
};

}  // namespace ppsynth
