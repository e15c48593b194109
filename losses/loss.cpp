#include "losses/loss.hpp"

#include "core/config/defaults_catalog.hpp"

namespace ppsynth {

std::vector<int> loss_layers(const json& params, const std::string& key_path) {
  if (!params.contains("layers") || !params["layers"].is_array() || params["layers"].empty())
    throw config_error(key_path + ".layers", "expected a non-empty array of layer indices");
  std::vector<int> out;
  for (auto& v : params["layers"]) {
    if (!v.is_number_integer() || v.get<int>() < 0)
      throw config_error(key_path + ".layers", "layer indices are integers >= 0");
    out.push_back(v.get<int>());
  }
  return out;
}

std::vector<int> given_layers(std::vector<int> layers, const std::string& key_path) {
  if (layers.empty()) throw config_error(key_path + ".layers", "expected a non-empty array of layer indices");
  return layers;
}

const torch::Tensor& layer_of(const Features& f, int l, const std::string& loss_name) {
  if (l < 0 || l >= static_cast<int>(f.size()))
    throw InputError("loss '" + loss_name + "' uses layer " + std::to_string(l) + " but the feature net has " +
                     std::to_string(f.size()) + " layers");
  return f[l];
}

}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("loss", ppsynth::LossRegistry)
