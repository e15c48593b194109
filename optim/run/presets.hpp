#pragma once
// Named presets: a run-config fragment layered between the defaults and the user's config.
//
//   defaults  <  preset  <  the config (and its parents)  <  --set
//
// Chosen by "preset": "fast" in a config, `--preset fast` on the command line, or
// `preset=fast` in a sweep's "set" or "grid". The config's own keys win over the preset's;
// the resolved config keeps the preset's name beside every value it set. Each preset is
// declared once, in presets.cpp, with what it trades (docs/performance.md, "Time to quality").
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

// name -> {"description": ..., "config": fragment}.
nlohmann::json presets();
// `config` with the fragment of its "preset" (if any) merged under it; errors name the key.
nlohmann::json apply_preset(const nlohmann::json& config);

}  // namespace ppsynth
