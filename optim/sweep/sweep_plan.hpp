#pragma once
// A sweep: many runs (configs x seeds x override grids) planned into one directory, executed
// anywhere (optim/sweep/sweep_executors.hpp: here with N processes, or as a SLURM job array)
// and gathered into statistics over seeds (optim/sweep/gather.hpp). One seed is one sample.
//
// A sweep spec (JSON; "parent" inherits like every config; unknown keys are refused):
//   { "name": "poisson_seeds",                 plain name (letters, digits, _ and -)
//     "runs": ["configs/runs/lines.json", ...], run configs (paths relative to the spec, or
//                                               "shared:...", or from the source root)
//     "figures": ["fig05", ...],                figure configs of configs/paper: each panel's
//                                               synthesised columns ("ours", registry methods)
//     "panels": ["a", "b"],                     only these panels of the figures (default all)
//     "seeds": [95, "96-99"],                   seeds and inclusive ranges ("95,97-98" too)
//     "grid": {"method.max_iterations": [40, 100]},  --set axes, every combination
//     "set": ["method.k=20"],                   --set overrides applied to every run (in figure
//                                               columns, method.* keys to "ours" only, as reproduce)
//     "quick": false,                           tiny settings (tests)
//     "resources": {"cpus": 2, "memory_mb": 4096, "time_minutes": 240} }  per task (SLURM)
//
// The plan (DIR/manifest.json) has one row per run: a stable id (a hash of the resolved config,
// seed and quick flag), the run directory DIR/runs/<id>, the resolved config, and the group
// (the same config with the seed left out) that gather pools seeds over. Planning again after
// an edit keeps the ids, and so the run directories and finished runs, of unchanged rows.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ppsynth {

struct SweepRow {
  std::string id;      // 12 hex digits
  std::string label;   // "<group label> seed <s>"
  std::string group;   // id of the config without its seed (rows pooled by gather)
  std::string group_label;
  std::string source;  // the run or figure config it came from
  std::vector<std::string> overrides;
  uint64_t seed = 0;
  bool quick = false;
  std::string dir;     // relative to the sweep directory: runs/<id>
  nlohmann::json config;  // resolved run config (seed included)
};

struct SweepResources {
  int cpus = 1;
  int memory_mb = 4096;
  int time_minutes = 240;
};

struct SweepManifest {
  std::string name;
  std::string spec_source;
  nlohmann::json spec;
  SweepResources resources;
  std::vector<SweepRow> rows;
};

// Reads a spec file and expands it (every run config resolved; errors name the file and key).
SweepManifest expand_sweep_spec(const std::string& spec_path);
// Same for a spec in memory; relative paths resolve against base_dir.
SweepManifest expand_sweep_spec(const nlohmann::json& spec, const std::string& source, const std::string& base_dir);

struct PlanSummary {
  std::string dir;
  size_t rows = 0, kept = 0, added = 0, dropped = 0;
};

// Writes DIR/manifest.json (DIR new or empty, or a sweep directory of ppsynth: re-planned in
// place, keeping what it holds). Rows dropped from the plan keep their run directories.
PlanSummary plan_sweep(const SweepManifest& manifest, const std::string& dir);

// Reads DIR/manifest.json; InputError naming it when absent or not a sweep's.
SweepManifest load_sweep(const std::string& dir);

// A short stable hash of a JSON value (FNV-1a 64 of its compact dump, 12 hex digits).
std::string json_id(const nlohmann::json& value);


}  // namespace ppsynth
