#pragma once
// One synthesis run, end to end, into a run directory:
//   output.txt (project format) + output.<exemplar format>.txt, exemplar_vs_output.png,
//   snapshots/stageNN.{txt,png} (Fig. 4), loss.csv + loss.png, config.json (resolved),
//   run.json (seed, revision, wall time per phase, per-stage iterations), metrics.json and
//   pcf.png (`ppsynth eval` of the output against the exemplar).
// The directory is built as "<dir>.partial" and renamed when complete: an interrupted run
// leaves no half-written run directory.
#include <string>

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

}  // namespace ppsynth::app
