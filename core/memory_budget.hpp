#pragma once
// Sizes a user controls (point counts, grid and image resolutions, upscaling) are checked
// against the memory they need before anything is allocated, so that an impossible request
// is an error with its number, not an allocation failure deep inside a library.
#include <string>

namespace ppsynth {

// The memory this process may use: MemAvailable of /proc/meminfo (else the physical memory),
// lowered by PPSYNTH_MEMORY_LIMIT_MB when set (tests, shared machines).
double available_memory_bytes();

// Throws InputError "<what> needs about X GiB; Y GiB are available" when `bytes` exceeds
// available_memory_bytes(). `what` names the parameter(s) that set the size.
void check_memory(double bytes, const std::string& what);

// The peak resident memory of this process so far (getrusage's ru_maxrss), MiB: what
// run.json and `ppsynth bench` report.
double peak_resident_mib();

// Hands the heap's free pages back to the kernel (glibc's malloc_trim; nothing elsewhere).
// A synthesis keeps freed memory on the heap so that every iteration reuses its buffers
// without page faults (optim/run/runtime.hpp); a run of many windows calls this at each
// window's end, or the heap's fragments add up window after window (how much:
// docs/lab/large_outputs.md, "Numbers that were in code comments").
void release_freed_memory();

}  // namespace ppsynth
