#pragma once
// One synthesis run, end to end, into a run directory of the run store
// (optim/run/run_store.hpp): synthesize() (optim/run/synthesize.hpp) with the observers that
// write progress, snapshots and the loss curve, checkpoints written atomically, then every
// output file.
// The directory is opened through RunDirectory (core/run_directory.hpp): it must be new or
// empty, or a ppsynth run directory with `force`; it is marked complete only when every
// output is written. A failed run removes what it wrote unless it left a checkpoint; an
// interrupted one keeps its checkpoint for resume_synthesis.
#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "optim/run/run_spec.hpp"
#include "optim/run/run_store.hpp"

namespace ppsynth {

// Where and how to run. quick: tiny settings (tests, --quick).
struct RunRequest {
  std::string dir;  // "" = runs/<name> (the config's name or the exemplar's stem, then a plain name)
  bool quick = false;
  bool force = false;  // replace a ppsynth run directory already there
  // Set (by a signal handler, say) to stop: the method saves a checkpoint at the end of the
  // iteration and RunInterrupted propagates; resume_synthesis continues the run.
  const std::atomic<bool>* stop = nullptr;
  // Told of every stage and iteration beside the run's own progress log, snapshot writer and
  // loss recorder (a front end's progress display, say).
  std::vector<SynthesisObserver*> observers;
};

// Thrown when request.stop stopped a run: its checkpoint is in `dir`, for resume_synthesis;
// `dir` is "" when it stopped before its first checkpoint (its directory is then removed).
class RunInterrupted : public std::runtime_error {
 public:
  explicit RunInterrupted(std::string d)
      : std::runtime_error(d.empty() ? "interrupted before the first checkpoint" : "interrupted; the checkpoint is in " + d),
        dir(std::move(d)) {}
  std::string dir;
};

// A new run of `spec` (run_spec.hpp: its exemplar read and its shape, seed and method resolved
// once; the directory's config.json, the checkpoint key and the log read them). Methods that
// can resume write checkpoint.bin into the directory at every stage boundary and every
// `checkpoint_seconds`; it is removed when the run completes.
RunOutcome run_synthesis(const RunSpec& spec, const RunRequest& request);
// The same for `resolved` (from resolve_run_config): load_run_spec, then the above.
RunOutcome run_synthesis(const nlohmann::json& resolved, const RunRequest& request);

// Continues the unfinished run in `dir` from its checkpoint (request.dir and quick are taken
// from the directory). The outputs equal those of the run never interrupted (same thread
// count; wall times aside). A checkpoint that does not belong to the directory's config.json
// (edited, copied from another run, damaged) is a CheckpointError saying what differs.
// With request.force the run starts afresh from its config.json instead (the same checks as a
// new run; the directory's files are replaced).
RunOutcome resume_synthesis(const std::string& dir, const RunRequest& request);

}  // namespace ppsynth
