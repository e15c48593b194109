#pragma once
// One synthesis run, end to end, into a run directory:
//   output.txt (project format) + output.<exemplar format>.txt, exemplar_vs_output.png,
//   snapshots/stageNN.{txt,png} (Fig. 4), loss.csv + loss.png, config.json (resolved),
//   run.json (seed, revision, wall time per phase, per-stage iterations), metrics.json and
//   pcf.png (`ppsynth eval` of the output against the exemplar).
// The directory is built as "<dir>.partial" and renamed when complete: an interrupted run
// leaves no half-written run directory.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/point_set.hpp"

namespace ppsynth::app {

struct RunOutcome {
  std::string dir;
  PointSet exemplar, initialization, output;
  nlohmann::json stats, metrics, config;
  double seconds = 0;
};

// `resolved`: from resolve_run_config. quick: tiny settings (tests, --quick).
RunOutcome run_synthesis(const nlohmann::json& resolved, const std::string& dir, bool quick);

// Reads a finished run directory back (config.json, run.json, output.txt, init.txt; the
// exemplar from its exemplar.txt copy, or the config's file for runs made before the copy). Throws InputError naming the file when something is missing.
RunOutcome load_run(const std::string& dir);

// True when two resolved run configs describe the same synthesis apart from the exemplar:
// everything but the keys that only label or decorate a run (name, description, snapshots,
// evaluate) and the exemplar's file name and format (exemplars are compared by content).
bool same_synthesis(const nlohmann::json& a, const nlohmann::json& b);

// A finished run directory under any of `roots` (each root itself or one of its direct
// subdirectories) made by the same synthesis (same_synthesis) at the same quick setting from
// the same exemplar points (so a generated exemplar in another report's folder matches);
// "" when none. Lets a report reuse long runs instead of repeating them (reproduce --reuse).
std::string find_matching_run(const nlohmann::json& resolved, bool quick, const std::vector<std::string>& roots);

}  // namespace ppsynth::app
