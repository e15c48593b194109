#include "optim/run/presets.hpp"

#include "core/config/config.hpp"
#include "core/config/defaults_catalog.hpp"
#include "core/error.hpp"

namespace ppsynth {

nlohmann::json presets() {
  using json = nlohmann::json;
  return json{
      // Issue 21: the Gabor method's quality in the least time on a CPU, measured over seeds
      // 95-99 on lines, poisson_n64c2_point, Tree1, Cattles and Fluid1 against the default
      // (docs/performance.md, "Time to quality"; lines: median 69 s over 5 seeds instead of 745 s idle):
      //   - bfloat16 network on the channels-last path (oneDNN's bf16 convolutions, AMX
      //     where the CPU has it: 0.18 s instead of 0.97 s per iteration on lines);
      //   - per-sigma grids: the coarse sigmas on coarser grids, the finest on the full one;
      //   - the "pattern" stopping rule: a sigma stage ends when its PCF stops improving, on
      //     its best checked iterate as the output square shows it ("end_on": "best"; ending
      //     on the last iterate, lines' PCF MSE was 1.54 x the default's, bimodal with the
      //     parked pairs of the last sigma), checked every 5 iterations (twice the candidates
      //     of the rule's default 10 for one PCF more per 10 iterations: poisson_n64c2_point's
      //     PCF MSE went from 1.14 x the default's to 0.90 x).
      // Read by 20 random crops instead of the quadrants (the frame left out), lines' PCF MSE
      // is 1.52 x the default's and Tree1's 1.11 x; ending on the last iterate it was 1.15 x
      // and 1.01 x (docs/performance.md): the best is judged on the whole square, border included.
      // 40 filters and the 9/d grid without the 128 floor were measured too and left out:
      // they cost Tree1's structure (PCF MSE 0.023 against 0.012).
      {"fast",
       {{"description", "bf16 network, per-sigma grids, stop when the pattern stops improving (checked every 5 iterations) and keep its best: lines in 62-124 s (median 69 s) instead of 745 s"},
        {"config",
         {{"method",
           {{"feature_net", {{"precision", "bfloat16"}}},
            {"grid", {{"per_sigma", true}}},
            {"convergence", {{"type", "pattern"}, {"end_on", "best"}, {"check_every", 5}}}}}}}}},
  };
}

nlohmann::json apply_preset(const nlohmann::json& config) {
  if (!config.is_object() || !config.contains("preset") || config["preset"].is_null()) return config;
  const auto& name = config["preset"];
  const auto all = presets();
  std::string known;
  for (auto it = all.begin(); it != all.end(); ++it) known += (known.empty() ? "" : ", ") + it.key();
  if (!name.is_string() || !all.contains(name.get<std::string>()))
    throw config_error("preset", "unknown preset " + name.dump() + " (known: " + known + "; null for none)");
  const auto& fragment = all[name.get<std::string>()]["config"];
  // A preset sets the Gabor method's parameters: another method would refuse them as unknown
  // keys; say why instead.
  if (fragment.contains("method") && config.contains("method") && config["method"].is_object() &&
      config["method"].value("type", "gabor") != "gabor")
    throw config_error("preset", "preset '" + name.get<std::string>() + "' sets the gabor method's parameters; this config's method is '" +
                                     config["method"]["type"].get<std::string>() + "'");
  return merge(fragment, config);
}

}  // namespace ppsynth

namespace {
[[maybe_unused]] const bool ppsynth_presets_kind = ppsynth::register_defaults_kind("preset", [] { return ppsynth::presets(); });
}  // namespace
