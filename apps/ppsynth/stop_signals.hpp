#pragma once
// SIGINT / SIGTERM for the commands that run long (synthesize, sweep run, sweep task): the
// first signal sets the flag the run library polls at the end of every iteration (it writes a
// checkpoint and stops); the handler is reset after it, so a second signal ends the process at
// once. exit_code_for_stop() is 130 for SIGINT, 143 for SIGTERM (as a shell reports them).
#include <atomic>

namespace ppsynth::app {

void install_stop_handlers();
const std::atomic<bool>* stop_flag();
int stop_signal();          // the signal that set the flag (0 if none)
const char* stop_signal_name();
int exit_code_for_stop();

}  // namespace ppsynth::app
