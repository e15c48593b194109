#include "models/feature_net.hpp"

#include "core/config/config.hpp"
#include "core/config/defaults_catalog.hpp"
#include "core/error.hpp"

namespace ppsynth {

void freeze(torch::nn::Module& m) {
  for (auto& p : m.parameters()) p.set_requires_grad(false);
}

nlohmann::json with_channels_for_classes(const nlohmann::json& spec, int num_classes, const std::string& key_path) {
  if (!spec.is_object() || !spec.contains("channels") || !spec["channels"].is_object()) return spec;
  const nlohmann::json& by_count = spec["channels"];
  const std::string kp = key_path + ".channels";
  for (auto it = by_count.begin(); it != by_count.end(); ++it)
    if (it.key() != "one_class" && it.key() != "several_classes")
      throw config_error(kp + "." + it.key(), "unknown key (a filter count by class count takes \"one_class\" and \"several_classes\")");
  for (const char* key : {"one_class", "several_classes"})
    if (!by_count.contains(key)) throw config_error(kp + "." + key, "missing (a filter count by class count needs both)");
  nlohmann::json out = spec;
  const char* chosen = num_classes > 1 ? "several_classes" : "one_class";
  out["channels"] = get_int(by_count, chosen, kp);  // a whole number; the network's bounds apply when it is made
  return out;
}

}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("feature_net", ppsynth::FeatureNetRegistry)
