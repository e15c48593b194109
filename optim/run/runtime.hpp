#pragma once
// Process-wide tuning a synthesis wants, as one call every front end makes before its first
// synthesis (the command in main(), a Python module on the first synthesize(), a test):
//   threads    Debian's LibTorch starts with one intra-op thread; use every core, or
//              PPSYNTH_THREADS (1..1024). Results depend on it in the last bits (reductions are
//              split across threads), so run.json and checkpoints record it.
//   allocator  glibc returns freed activation buffers to the kernel and maps large blocks
//              afresh, so every iteration page-faults them in again; ppsynth keeps freed memory
//              on the heap instead (PPSYNTH_MALLOC=system keeps glibc's defaults).
// Nothing happens at load time: linking the library changes neither.
namespace ppsynth {

struct RuntimeSettings {
  int threads = 0;               // applied intra-op thread count
  bool keeps_freed_memory = false;
};

// Reads PPSYNTH_THREADS and PPSYNTH_MALLOC (InputError naming the variable when malformed),
// applies them and returns what was applied. Calling it again re-reads the thread count; the
// allocator is set once per process.
RuntimeSettings configure_runtime();

// PPSYNTH_THREADS as a user set it (1..1024), 0 when unset; InputError when malformed.
int threads_from_environment();

}  // namespace ppsynth
