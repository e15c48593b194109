#pragma once
// One synthesis run, end to end, into a run directory:
//   output.txt (project format) + output.<exemplar format>.txt, exemplar_vs_output.png,
//   snapshots/stageNN.{txt,png} (Fig. 4), loss.csv + loss.png, config.json (resolved),
//   run.json (seed, revision, wall time per phase, per-stage iterations), metrics.json and
//   pcf.png (`ppsynth eval` of the output against the exemplar).
// The directory is opened through RunDirectory (core/run_directory.hpp): it must be new or
// empty, or a ppsynth run directory with `force`; it is marked complete only when every
// output is written. A failed run removes what it wrote unless it left a checkpoint; an
// interrupted one keeps its checkpoint for resume_synthesis.
#include <atomic>
#include <stdexcept>
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

// Where and how to run. quick: tiny settings (tests, --quick).
struct RunRequest {
  std::string dir;  // "" = runs/<name> (the config's name or the exemplar's stem, then a plain name)
  bool quick = false;
  bool force = false;  // replace a ppsynth run directory already there
  // Set (by a signal handler, say) to stop: the method saves a checkpoint at the end of the
  // iteration and SynthesisInterrupted propagates; resume_synthesis continues the run.
  const std::atomic<bool>* stop = nullptr;
};

// Thrown when request.stop stopped a run: its checkpoint is in `dir`, for resume_synthesis.
class RunInterrupted : public std::runtime_error {
 public:
  explicit RunInterrupted(std::string d)
      : std::runtime_error("interrupted; the checkpoint is in " + d), dir(std::move(d)) {}
  std::string dir;
};

// True when the config's method checkpoints (and so honours RunRequest::stop).
bool can_resume(const nlohmann::json& resolved);

// A new run of `resolved` (from resolve_run_config). Methods that can resume write
// checkpoint.bin into the directory at every stage boundary and every
// `checkpoint_seconds`; it is removed when the run completes.
RunOutcome run_synthesis(const nlohmann::json& resolved, const RunRequest& request);

// Continues the unfinished run in `dir` from its checkpoint (request.dir and quick are taken
// from the directory). The outputs equal those of the run never interrupted (same thread
// count; wall times aside).
RunOutcome resume_synthesis(const std::string& dir, const RunRequest& request);

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
// "" when none. Only directories marked complete count. Lets a report reuse long runs instead of repeating them (reproduce --reuse).
std::string find_matching_run(const nlohmann::json& resolved, bool quick, const std::vector<std::string>& roots);

}  // namespace ppsynth::app
