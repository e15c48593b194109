#include "optim/run/presets.hpp"

#include "core/config/config.hpp"
#include "core/config/defaults_catalog.hpp"
#include "core/error.hpp"
#include "core/processor.hpp"
#include "models/feature_net.hpp"
#include "optim/run/runtime.hpp"

namespace ppsynth {

nlohmann::json presets() {
  using json = nlohmann::json;
  return json{
      // The Gabor method's quality in the least time on a CPU (docs/explanation/performance.md,
      // "Which knobs trade what", and the lab pages it links hold the measurements behind each knob):
      //   - the network in bf16 where the CPU has bf16 units ("auto"): oneDNN's bf16
      //     convolutions run several times float32's rate there;
      //   - per-sigma grids: a map blurred by sigma holds no detail finer than sigma, so the
      //     coarse sigmas run on coarser grids and the finest keeps the full one;
      //   - the "pattern" stopping rule: a sigma stage ends when the PCF of its points stops
      //     improving, checked every 5 iterations, and ends on its best checked iterate (a
      //     stage whose pattern got worse while its loss still fell gives back what it lost);
      // On a CUDA device "auto" is bf16 from compute capability 8.0 (bf16 tensor cores).
      // Where bf16 would be emulated, the network runs float32, and "without_bf16_units" buys
      // back the time bf16 would have saved with fewer filters, where that costs no quality:
      // 64 float32 filters keep each class and pair as close to the exemplar as the 120 bf16
      // filters of a bf16 machine, for one class and for several (docs/lab/real_scale).
      {"fast",
       {{"description", "the network in bf16 where the device has bf16 units (a CPU's AVX512_BF16 or AMX, a CUDA card's tensor cores), per-sigma grids, and stages that stop when the "
                        "pattern stops improving and keep its best; without bf16 units, a float32 network of 64 filters"},
        {"config",
         {{"method",
           {{"feature_net", {{"precision", "auto"}}},
            {"grid", {{"per_sigma", true}}},
            {"convergence", {{"type", "pattern"}, {"end_on", "best"}, {"check_every", 5}}}}}}},
        {"without_bf16_units",
         {{"method", {{"feature_net", {{"channels", 64}}}}}}}}},
  };
}

namespace {

const nlohmann::json& preset_entry(const nlohmann::json& all, const nlohmann::json& name) {
  std::string known;
  for (auto it = all.begin(); it != all.end(); ++it) known += (known.empty() ? "" : ", ") + it.key();
  if (!name.is_string() || !all.contains(name.get<std::string>()))
    throw config_error("preset", "unknown preset " + name.dump() + " (known: " + known + "; null for none)");
  return all[name.get<std::string>()];
}

bool takes_float32_variant(const nlohmann::json& entry, bool bf16_units) {
  return entry.contains("without_bf16_units") && !bf16_units;
}

// The device a config being resolved names (runtime.device, the CPU by default), as this
// process sees it.
DeviceCapabilities config_device(const nlohmann::json& config) {
  if (config.contains("runtime") && config["runtime"].is_object() && config["runtime"].contains("device"))
    return capabilities_of_device(config["runtime"]["device"]);
  return cpu_capabilities();
}

// The preset's network keys tune the default "random" network (its precision, its filter
// count). A config that names another network ("identity": Fig. 12b's Gabor maps alone;
// "fixed_bank": Fig. 10's banks) has no such knobs: the preset leaves out the keys that
// network does not declare, so a preset applies to every ablation panel, while a key the
// user writes that the network lacks is still refused by name.
nlohmann::json only_what_the_network_takes(nlohmann::json fragment, const nlohmann::json& config) {
  if (!fragment.contains("method") || !fragment["method"].contains("feature_net") || !config.contains("method") ||
      !config["method"].is_object() || !config["method"].contains("feature_net"))
    return fragment;
  const nlohmann::json& net = config["method"]["feature_net"];
  if (!net.is_object() || !net.contains("type") || !net["type"].is_string()) return fragment;
  const auto& registry = FeatureNetRegistry::instance();
  if (!registry.contains(net["type"].get<std::string>())) return fragment;  // the registry names the error when the net is made
  const nlohmann::json& declared = registry.entry(net["type"].get<std::string>()).defaults;
  nlohmann::json& keys = fragment["method"]["feature_net"];
  for (auto it = keys.begin(); it != keys.end();) it = declared.contains(it.key()) ? std::next(it) : keys.erase(it);
  if (keys.empty()) fragment["method"].erase("feature_net");
  return fragment;
}

}  // namespace

nlohmann::json preset_fragment(const std::string& name, bool bf16_units) {
  const nlohmann::json all = presets();
  const nlohmann::json& entry = preset_entry(all, name);
  return takes_float32_variant(entry, bf16_units) ? merge(entry["config"], entry["without_bf16_units"]) : entry["config"];
}

nlohmann::json preset_fragment(const std::string& name) { return preset_fragment(name, cpu_isa().native_bf16); }

nlohmann::json apply_preset(const nlohmann::json& config) {
  if (!config.is_object() || !config.contains("preset") || config["preset"].is_null()) return config;
  const auto& name = config["preset"];
  preset_entry(presets(), name);  // the name's error first
  const nlohmann::json fragment = preset_fragment(name.get<std::string>(), config_device(config).bf16());
  // A preset sets the Gabor method's parameters: another method would refuse them as unknown
  // keys; say why instead.
  if (fragment.contains("method") && config.contains("method") && config["method"].is_object() &&
      config["method"].value("type", "gabor") != "gabor")
    throw config_error("preset", "preset '" + name.get<std::string>() + "' sets the gabor method's parameters; this config's method is '" +
                                     config["method"]["type"].get<std::string>() + "'");
  return merge(only_what_the_network_takes(fragment, config), config);
}

nlohmann::json preset_record(const nlohmann::json& preset, const nlohmann::json& runtime_device) {
  if (!preset.is_string()) return nullptr;
  const nlohmann::json all = presets();
  const nlohmann::json& entry = preset_entry(all, preset);
  const DeviceCapabilities device = capabilities_of_device(runtime_device);
  const bool f32 = takes_float32_variant(entry, device.bf16());
  const std::string kind = device.describe();
  std::string reason = "one variant for every processor";
  if (entry.contains("without_bf16_units") && !device.cuda)
    reason = f32 ? "no bf16 units in use on this CPU (" + kind + ")" : "the CPU's bf16 units are in use (" + kind + ")";
  else if (entry.contains("without_bf16_units"))
    reason = f32 ? "no bf16 tensor cores known on the CUDA device (" + kind + "; they start at compute capability 8.0)"
                 : "the CUDA device's bf16 tensor cores (" + kind + ")";
  return {{"name", preset}, {"variant", f32 ? kPresetWithoutBf16Units : kPresetEveryProcessor}, {"reason", reason}};
}

namespace {

// Erases from `config` every leaf of `fragment` that `config` holds with the same value, and
// the objects that leaves empty.
void erase_equal_leaves(nlohmann::json& config, const nlohmann::json& fragment) {
  if (!config.is_object() || !fragment.is_object()) return;
  for (auto it = fragment.begin(); it != fragment.end(); ++it) {
    if (!config.contains(it.key())) continue;
    nlohmann::json& mine = config[it.key()];
    if (it.value().is_object() && mine.is_object()) {
      erase_equal_leaves(mine, it.value());
      if (mine.empty()) config.erase(it.key());
    } else if (mine == it.value()) {
      config.erase(it.key());
    }
  }
}

}  // namespace

nlohmann::json as_every_processor_variant(nlohmann::json resolved, const std::string& variant) {
  if (variant != kPresetWithoutBf16Units || !resolved.is_object() || !resolved.contains("preset") || !resolved["preset"].is_string())
    return resolved;
  const nlohmann::json all = presets();
  const std::string name = resolved["preset"].get<std::string>();
  if (!all.contains(name) || !all[name].contains("without_bf16_units")) return resolved;
  erase_equal_leaves(resolved, all[name]["without_bf16_units"]);
  return resolved;
}

}  // namespace ppsynth

namespace {
[[maybe_unused]] const bool ppsynth_presets_kind = ppsynth::register_defaults_kind("preset", [] { return ppsynth::presets(); });
}  // namespace
