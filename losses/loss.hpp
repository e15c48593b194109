#pragma once
// FeatureLoss: the features of the output -> a scalar, against targets taken once per sigma
// from the exemplar's features (paper §3.1, §4.2). A loss is one class plus one
// PPSYNTH_REGISTER line at the end of its .cpp; configs name it by "type":
//   {"losses": [{"type": "gram", "layers": [0,1,2], "weight": 0.08},
//               {"type": "correlation", "layers": [2], "weight": 1.0}]}
// Every loss accepts "weight" and "layers" (indices into [F1, F2, F3]).
#include <torch/torch.h>

#include <string>
#include <vector>

#include "core/registry.hpp"
#include "models/feature_net.hpp"

namespace ppsynth {

struct LossContext {
  int upscale = 2;     // u: the output has u^2 times the exemplar's pixels per layer
  uint64_t seed = 95;  // for losses that draw random directions
};

class FeatureLoss {
 public:
  virtual ~FeatureLoss() = default;
  // Stores the targets from the exemplar's features (called once per sigma stage).
  virtual void set_target(const Features& exemplar, const LossContext& ctx) = 0;
  // The unweighted loss of the output features.
  virtual torch::Tensor forward(const Features& output) = 0;
};

using LossRegistry = Registry<FeatureLoss>;

// Reads "layers" from a loss spec and checks the indices (named key path on error): a Python
// loss's, whose keys are its own JSON. A compiled loss reads its layers through its table and
// checks them with given_layers.
std::vector<int> loss_layers(const json& params, const std::string& key_path);
// `layers` when not empty; else the config_error loss_layers gives, naming <key_path>.layers.
std::vector<int> given_layers(std::vector<int> layers, const std::string& key_path);
// The layer of `f` for index l, or an error naming the loss when the net is shallower.
const torch::Tensor& layer_of(const Features& f, int l, const std::string& loss_name);

// The two keys every compiled loss declares, worded once for the reference: the feature
// layers it compares and its weight in the sum. O has members `layers` and `weight`.
template <class O>
std::vector<Param<O>> layer_loss_params() {
  return {param("layers", &O::layers, "int [0, 15]", "the feature layers it compares (indices into the net's)"),
          param("weight", &O::weight, "[0, inf)", "its weight in the sum of the losses")};
}

}  // namespace ppsynth
