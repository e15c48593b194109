#pragma once
// A run config as the readers of a run take it -- gather, reproduce and its report, the sweep's
// executor (a manifest's rows), the bench -- typed: read through RunOptions' table
// (run_config.hpp), the one place that knows the keys, instead of each reader picking
// "seed", "method.type" or "runtime.device" out of the JSON by name.
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "optim/run/run_config.hpp"

namespace ppsynth {

struct TypedRunOptions {
  RunOptions options;       // every key through RunOptions' table, runtime's values checked
  uint64_t seed = 0;        // options.seed
  std::string method_type;  // options.method's "type"
};

// `config`: a resolved run config (a run directory's config.json, a sweep manifest's row, one
// just resolved). `source`: where it was read (a file, "manifest.json rows[2].config"). A key of
// a wrong type or out of range is an InputError naming `source` and the key.
TypedRunOptions run_options_of(const nlohmann::json& config, const std::string& source);

}  // namespace ppsynth
