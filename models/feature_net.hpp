#pragma once
// FeatureNet: 1 x C x H x W maps -> the features of every block [F1, F2, F3] (paper §4.1).
// Implementations: "random" (the paper's random-filter network), "fixed_bank" (Gaussian,
// Sobel and derivative banks of the Fig. 10 ablation), "identity" (Gabor maps only, Fig. 12b).
// All are frozen: their parameters never require gradients, so backward computes only the
// input gradient (the published code also computes weight gradients and throws them away).
#include <torch/torch.h>

#include <vector>

#include "core/registry.hpp"

namespace ppsynth {

using Features = std::vector<torch::Tensor>;  // one 1 x C_l x H_l x W_l tensor per block

class FeatureNet : public torch::nn::Module {
 public:
  virtual Features forward(const torch::Tensor& maps) = 0;
  // What the net decided when it was made that its config left open (the "random" net's
  // precision under "auto", and why), merged into the resolved config a run records.
  virtual nlohmann::json choices() const { return nlohmann::json::object(); }
};

// Created with the number of input channels and the run's seed (for random weights).
using FeatureNetRegistry = Registry<FeatureNet, int /*in_channels*/, uint64_t /*seed*/>;

// A network spec whose filter count depends on the exemplar's class count,
//   "channels": {"one_class": 64, "several_classes": 120},
// with that count resolved to a number for an exemplar of `num_classes` classes; any other
// spec returns as it is: a config may size the network by the exemplar's class count, as a
// multi-class exemplar's classes share one network. Errors name `key_path`.channels.
nlohmann::json with_channels_for_classes(const nlohmann::json& spec, int num_classes, const std::string& key_path);

// Freezes every parameter of `m` (requires_grad = false).
void freeze(torch::nn::Module& m);

}  // namespace ppsynth
