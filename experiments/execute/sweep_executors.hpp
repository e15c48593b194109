#pragma once
// Where the runs of a sweep execute. Both executors run `ppsynth sweep task DIR --row ID
// --manifest HASH` for each row that is not done (experiments/execute/sweep_runs.hpp), so a task that
// runs again resumes its checkpoint, a finished run is never repeated, and a plan changed
// since never makes a task run another row:
//   local  N task processes at once on this machine, holding the sweep's lock (SweepLock: a
//          second executor or a re-plan is refused meanwhile), the cores split between them
//          (PPSYNTH_THREADS per task, unless the user set it), each in its own process group
//          so that Ctrl-C reaches only the executor, which stops every task with SIGTERM (each
//          checkpoints). Rows that run on a CUDA device share the cards: several runs per
//          card at once (a small synthesis leaves most of a card idle), as many as the card's
//          memory holds at the spec's per-task memory (resources.memory_mb), at most its
//          share of the cores; with several cards each task gets one (CUDA_VISIBLE_DEVICES).
//          plan_local_slots decides, from what the machine has (a pure function).
//   slurm  an sbatch job-array script written into the sweep directory and submitted: the
//          array index picks the row's id from a list in the script; --requeue and a SIGTERM
//          ahead of the time limit let a preempted or timed-out task checkpoint and resume
//          when it runs again. Built only from checked values (the manifest, as
//          core/sweep_manifest.hpp reads it; partition and account names; resources in range).
#include <atomic>
#include <string>
#include <vector>

#include "experiments/plan/sweep_plan.hpp"

namespace ppsynth {

struct LocalExecution {
  std::string binary;   // the ppsynth executable that runs `sweep task`
  int jobs = 0;         // tasks at once; 0: 1 on the CPU, the cards' room (plan_local_slots) for CUDA rows
  int threads = 0;      // per task; 0 = PPSYNTH_THREADS when set, else the machine's cores / jobs (at least 1)
  int runs_per_device = 0;  // CUDA rows: runs at once on each card; 0: as many as its memory holds
};

// What the executor sees of the machine and the rows left to run.
struct LocalMachine {
  int cores = 1;
  int env_threads = 0;                     // PPSYNTH_THREADS as the user set it; 0 unset
  std::vector<double> card_memory_bytes;   // one per CUDA card this process sees (0: unknown)
};
struct LocalWork {
  size_t rows = 0;             // rows to run
  bool on_cuda = false;        // some row runs on a CUDA device (runtime.device cuda, cuda:N, or auto here)
  bool any_card = true;        // every CUDA row names "cuda", "cuda:0" or "auto": a task may be given any card
  double run_memory_bytes = 0; // a run's memory (the spec's resources.memory_mb)
};
struct LocalSlots {
  int jobs = 1, threads = 1;
  int runs_per_device = 0;        // CUDA rows: runs at once per card; 0 on the CPU
  std::vector<int> card_of_slot;  // per slot, the card its tasks see alone (CUDA_VISIBLE_DEVICES); -1: no change
  std::string reason;             // what the log says
};
LocalSlots plan_local_slots(const LocalExecution& how, const LocalMachine& machine, const LocalWork& work);

struct ExecutionSummary {
  size_t done = 0, failed = 0, interrupted = 0, skipped = 0;  // skipped: done or running already
};

// Runs every row that is not done or running. Returns when all ran, or when *stop turned true
// (then every running task is stopped with SIGTERM and waited for).
ExecutionSummary execute_local(const std::string& sweep_dir, const LocalExecution& how, const std::atomic<bool>* stop);

struct SlurmExecution {
  std::string binary;                    // absolute path of ppsynth on the cluster's nodes
  std::string partition, account;        // when not empty: letters, digits, '_', '-' and '.'
  std::vector<std::string> sbatch_options;  // extra "#SBATCH" options, e.g. "--qos=long" (printable, one line each)
  int cpus = 0, memory_mb = 0, time_minutes = 0;  // 0 = the spec's resources; else in their range
  int max_parallel = 0;                  // array throttle (%N); 0 = none
};

// The job-array script for the rows that are not done (empty when every row is done).
std::string slurm_script(const std::string& sweep_dir, const SweepManifest& m, const SlurmExecution& how);

// Writes the script to DIR/sweep.sbatch and submits it with sbatch; returns the job id.
std::string submit_slurm(const std::string& sweep_dir, const std::string& script);

// "0-3,5,7-8": array indices compressed into ranges.
std::string compress_indices(const std::vector<size_t>& indices);

}  // namespace ppsynth
