#pragma once
// A synthesis run's config (the "spec" of optim/run/synthesize.hpp): which exemplar, which
// method (with its own parameters), seed, upscaling, checkpoints. Top-level defaults live in
// run_config.cpp; method defaults live with each method's registration. Used by every front
// end: `synthesize`, `reproduce`, `bench`, the library call.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/formats/format_options.hpp"
#include "core/output_shape.hpp"
#include "core/point_set.hpp"
#include "optim/run/runtime.hpp"

namespace ppsynth {

using json = nlohmann::json;

// The top-level keys of a run config, declared once (run_config.cpp's table); "output" and
// "runtime" are blocks with tables of their own. The method's spec (its part's keys) and the
// seed (a whole number up to 2^63 - 1: is_seed) stay JSON here. A resolved config read
// through the table (RunOptions::params().read, core/config/params.hpp) is what the run layer
// reads (RunSpec::options, run_spec.hpp).
struct RunOptions {
  std::string name;
  std::string description;
  std::string exemplar;
  std::string format = "auto";
  std::string scaling = "per-axis";
  bool merge_classes = false;
  json init_file;
  json preset;
  json seed = 95;
  int upscale = 2;
  OutputOptions output;
  json method = json{{"type", "gabor"}};
  bool snapshots = true;
  bool evaluate = true;
  double checkpoint_seconds = 60;
  RuntimeOptions runtime;
  static const ParamTable<RunOptions>& params();
};

json run_defaults();

// Resolves a config (file or built) + "--set" overrides: defaults merged, unknown keys refused,
// the method's parameters merged with its registered defaults.
json resolve_run_config(json config, const std::vector<std::string>& overrides);

// A run directory's config.json as a resume takes it: a resolved config, which resolving again
// leaves as it is (core/run_json.hpp's checks, then every key's as resolve_run_config has it).
// A hand edit that resolve_run_config refuses, or one it would change, is an InputError naming
// the file and the key.
json read_resolved_run_config(const std::string& path);

// Loads the exemplar a resolved config names ("shared:" paths allowed); a config used only
// in memory (synthesize() with an exemplar at hand) needs none. `read_as` (when given) gets the
// format the file was read as (the config's "format", or the detected one for "auto").
PointSet load_exemplar(const json& resolved, Format* read_as = nullptr);
// The explicit initialization of "init_file", if any.
std::optional<PointSet> load_initialization(const json& resolved);

}  // namespace ppsynth
