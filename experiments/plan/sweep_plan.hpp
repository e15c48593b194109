#pragma once
// A sweep: many runs (configs x seeds x override grids) planned into one directory, executed
// anywhere (experiments/execute/sweep_executors.hpp: here with N processes, or as a SLURM job array)
// and gathered into statistics over seeds (experiments/gather/gather.hpp). One seed is one sample.
//
// A sweep spec (JSON; "parent" inherits like every config; unknown keys are refused):
//   { "name": "poisson_seeds",                 plain name (letters, digits, _ and -)
//     "runs": ["configs/runs/lines.json", ...], run configs (paths relative to the spec, or
//                                               "shared:...", or from the source root)
//     "figures": ["fig05", ...],                figure configs of configs/paper: each panel's
//                                               synthesized columns ("ours", registry methods)
//     "panels": ["a", "b"],                     only these panels of the figures (default all)
//     "seeds": [95, "96-99"],                   seeds and inclusive ranges ("95,97-98" too)
//     "grid": {"method.max_iterations": [40, 100]},  --set axes, every combination (an axis
//                                               whose values make the same runs, such as
//                                               "description" or "evaluate", is refused)
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

#include "core/sweep_manifest.hpp"

namespace ppsynth {

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
// A re-plan is refused while any row of the plan runs (its run directory is locked) or while
// another process holds the sweep (SweepLock: an executor, another plan). Rows queued on a
// cluster are addressed by id (sweep_runs.hpp), so a re-plan leaves them intact: a kept row
// runs as planned, a dropped one is refused by its task.
PlanSummary plan_sweep(const SweepManifest& manifest, const std::string& dir);

// Reads DIR/manifest.json, every value checked (core/sweep_manifest.hpp); InputError naming
// it when absent, malformed or not a sweep's.
SweepManifest load_sweep(const std::string& dir);

// One process at a time works on a sweep as a whole: `sweep plan` and `sweep run --local` hold
// this lock (an advisory lock on the sweep directory, released by the kernel when the process
// ends) for as long as they run; a second is refused at once, naming `what` it was to do.
class SweepLock {
 public:
  SweepLock(const std::string& dir, const std::string& what);
  ~SweepLock();
  SweepLock(const SweepLock&) = delete;
  SweepLock& operator=(const SweepLock&) = delete;

 private:
  int fd_ = -1;
};


}  // namespace ppsynth
