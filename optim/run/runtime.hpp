#pragma once
// Process-wide tuning a synthesis wants, as one call every front end makes before its first
// synthesis (the command in main(), a Python module on the first synthesize(), a test):
//   threads    Debian's LibTorch starts with one intra-op thread; use every core this
//              process may run on (its CPU affinity: what taskset, a cpuset or SLURM's binding
//              leaves it), or PPSYNTH_THREADS (1..1024). More threads than those cores is
//              allowed (a user may mean to oversubscribe) but warned about, naming the variable,
//              the value and the core count: the threads then take turns, and a synthesis runs
//              many times slower. Results depend on the count in the last bits (reductions are
//              split across threads), so run.json and checkpoints record it.
//   allocator  glibc returns freed activation buffers to the kernel and maps large blocks
//              afresh, so every iteration page-faults them in again; ppsynth keeps freed memory
//              on the heap instead (PPSYNTH_MALLOC=system keeps glibc's defaults).
// Nothing happens at load time: linking the library changes neither.
//
// The device of a synthesis is the config's "runtime" object (runtime_defaults()), applied per
// synthesis by apply_device_settings:
//   device         "cpu" (the default), "cuda", "cuda:N", or "auto" (the first CUDA device
//                  when this process sees one, else the CPU). Every tensor of the Gabor method
//                  lives there; the baselines run on the CPU whatever it says.
//   tf32           CUDA only: float32 convolutions and matrix products on TF32 tensor cores
//                  (a 10-bit mantissa in the products; false keeps IEEE float32 there too).
//                  null (the default) or "auto": the device decides: on where it has them
//                  (compute capability 8.0 and later), as PyTorch's own convolutions default to.
//   deterministic  CUDA only: cuDNN's deterministic algorithms without autotuning, and
//                  LibTorch's deterministic algorithms (the Gabor maps' backward then sums
//                  per point by a gather instead of atomics, models/per_point_sum.hpp), so
//                  the same config and seed give the same output. false: cuDNN autotuning
//                  (it times its algorithms and keeps the fastest, which may differ from run
//                  to run in the last bits). On the CPU every run is deterministic given the
//                  thread count.
// What was chosen and why (decide_device_settings, a pure function of the device's
// capabilities) goes into run.json's method_stats.runtime.choices.
#include <string>

#include <nlohmann/json.hpp>

#include "models/device_capabilities.hpp"

namespace ppsynth {

struct RuntimeSettings {
  int threads = 0;               // applied intra-op thread count
  bool keeps_freed_memory = false;
};

// Reads PPSYNTH_THREADS, PPSYNTH_MALLOC and PPSYNTH_GABOR_MAPS (InputError naming the variable
// when malformed), applies them and returns what was applied. Calling it again re-reads the
// thread count; the allocator is set once per process. Only what synthesizes calls it (the
// commands that do, before they write anything; Python's first synthesize()): a command that
// does not synthesize never reads these variables, so a bad value does not stop it.
RuntimeSettings configure_runtime();
// The checks of configure_runtime without applying anything, for a process whose children
// synthesize (`sweep run --local`): a bad value fails once there, not in every task.
void check_runtime_environment();
// The cores this process may run on: its CPU affinity, else every online core.
int usable_cores();

struct DeviceSettings {
  std::string device = "cpu";  // "cpu" or "cuda:N"
  bool tf32 = false;           // applied (CUDA only)
  bool deterministic = true;   // applied (CUDA only; the CPU always is)
};

// The settings a CUDA device gets, and why: TF32 from runtime.tf32 (true, false, or null or
// "auto") and the device; cuDNN autotuning exactly when runtime.deterministic is false (autotuning
// may pick another algorithm on each run, and so other bits).
struct DeviceDecision {
  bool tf32 = false;
  bool autotune = false;
  std::string tf32_reason, autotune_reason;
  nlohmann::json record(const DeviceCapabilities& device) const;  // run.json's runtime.choices
};
DeviceDecision decide_device_settings(const DeviceCapabilities& device, const nlohmann::json& tf32, bool deterministic);

// The capabilities of a runtime.device value as this process resolves it ("auto": the first
// CUDA device if it sees one): what a preset's variant is chosen by before the run starts. A
// CUDA device this process cannot see has its capability unknown.
DeviceCapabilities capabilities_of_device(const nlohmann::json& device);

template <class T>
class ParamTable;

// The run config's "runtime" block (above): its keys declared once (runtime.cpp's table).
struct RuntimeOptions {
  nlohmann::json device = "cpu";
  nlohmann::json tf32;  // null: the device decides
  bool deterministic = true;
  static const ParamTable<RuntimeOptions>& params();
};

// {"device": "cpu", "tf32": null, "deterministic": true}: RuntimeOptions{} written out.
nlohmann::json runtime_defaults();
// Checks a resolved "runtime" object's values (config_error naming the key), without
// asking which devices this process has: a config can be resolved on a machine that will not
// run it.
void check_runtime(const nlohmann::json& runtime);
// Resolves "auto", refuses a CUDA device this process cannot use (InputError naming
// runtime.device: a LibTorch without CUDA, or no such device), and sets the process-wide
// CUDA flags (TF32, cuDNN's algorithm choice, deterministic algorithms) for the synthesis.
DeviceSettings apply_device_settings(const RuntimeOptions& runtime);
// PPSYNTH_THREADS as a user set it (1..1024), 0 when unset; InputError when malformed.
int threads_from_environment();

}  // namespace ppsynth
