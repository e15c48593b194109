#pragma once
// Named presets: a run-config fragment layered between the defaults and the user's config.
//
//   defaults  <  preset  <  the config (and its parents)  <  --set
//
// Chosen by "preset": "fast" in a config, `--preset fast` on the command line, or
// `preset=fast` in a sweep's "set" or "grid". The config's own keys win over the preset's;
// the resolved config keeps the preset's name beside every value it set. Each preset is
// declared once, in presets.cpp, with what it trades (docs/explanation/performance.md,
// "Which knobs trade what").
//
// A preset may differ by device: its "config" holds for every device, and its
// "without_bf16_units" fragment is merged over it where the network's bf16 would not run
// natively: a CPU without AVX512_BF16 or AMX in use (core/processor.hpp), a CUDA device below
// compute capability 8.0 (models/device_capabilities.hpp), since there the knobs that make
// bf16 pay cost time instead. The device is the config's runtime.device as this process
// resolves it. run.json records which variant ran and why (preset_record).
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

// name -> {"description": ..., "config": fragment[, "without_bf16_units": fragment]}.
nlohmann::json presets();
// The fragment a preset contributes on this CPU; on a device with or without bf16 units in
// use (`bf16_units`: DeviceCapabilities::bf16()).
nlohmann::json preset_fragment(const std::string& name);
nlohmann::json preset_fragment(const std::string& name, bool bf16_units);
// `config` with the fragment of its "preset" (if any) merged under it; errors name the key.
// Where the config names a feature network other than the default one, the preset's network
// keys that network does not declare are left out (an ablation's "identity" net has no
// precision to set).
nlohmann::json apply_preset(const nlohmann::json& config);
// For run.json: {"name", "variant": "every processor" | "without bf16 units", "reason"} of a
// run's preset (RunOptions::preset, run_config.hpp) on its device (runtime.device); null
// without a preset.
nlohmann::json preset_record(const nlohmann::json& preset, const nlohmann::json& device);

// The variants preset_record names.
inline constexpr const char* kPresetEveryProcessor = "every processor";
inline constexpr const char* kPresetWithoutBf16Units = "without bf16 units";

// A run config resolved under its preset's `variant` (preset_record's), as the preset's
// "every processor" variant resolves it: one made "without bf16 units" loses the values that
// variant's fragment set, where it holds exactly them; any other comes back unchanged. Two
// runs of one request on machines of both kinds then compare equal (run_store's
// find_matching_run), so a sweep kept across machines (docs/lab/reproduce_runs) reuses each
// run as its preset's run, whichever kind made it; run.json says which did.
nlohmann::json as_every_processor_variant(nlohmann::json resolved, const std::string& variant);

}  // namespace ppsynth
