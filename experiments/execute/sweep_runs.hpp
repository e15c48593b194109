#pragma once
// The runs of a sweep (experiments/plan/sweep_plan.hpp), read from the run directories themselves,
// so status works the same after a cluster has forgotten its jobs:
//   done         the run directory is marked complete
//   running      unfinished, and a process holds its lock
//   interrupted  unfinished, nobody holds it: the next task resumes its checkpoint
// (for both, how far: the stage begun last and the last checkpoint, run_progress_text)
//   failed       the last task failed (DIR/logs/<id>.failed holds the error); the next retries
//   pending      not started
// run_sweep_task runs one row, named by its id (never by its position: a re-plan keeps the
// ids of unchanged rows and may move them): skips a finished run, resumes an interrupted one,
// starts the rest. The `ppsynth sweep task` command, every local worker and every SLURM array
// task are this call.
#include <atomic>
#include <string>
#include <vector>

#include "experiments/plan/sweep_plan.hpp"

namespace ppsynth {

enum class RowState { Pending, Running, Interrupted, Failed, Done };
const char* row_state_name(RowState s);

struct RowStatus {
  const SweepRow* row = nullptr;
  RowState state = RowState::Pending;
  // The error of a failed run; the wall time of a finished one; the progress of an unfinished one.
  std::string detail;
};

std::vector<RowStatus> sweep_status(const std::string& sweep_dir, const SweepManifest& m);

// Runs the row `row_id` of the sweep in `sweep_dir`; returns its state afterwards (Done).
// `manifest_hash` (sweep_manifest_hash; "" = not checked) is the plan the task was given: a
// plan changed since is noted, and a row no longer in it is an InputError. Throws what the run
// throws (RunInterrupted when *stop turned true: the checkpoint is kept), after recording a
// failure in DIR/logs/<id>.failed.
RowState run_sweep_task(const std::string& sweep_dir, const std::string& row_id, const std::string& manifest_hash,
                        const std::atomic<bool>* stop);

}  // namespace ppsynth
