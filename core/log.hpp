#pragma once
// Logging is spdlog's default logger; this only sets its level from -v / -q counts and a
// compact pattern. Libraries log through spdlog::info / debug directly.
#include <spdlog/spdlog.h>

namespace ppsynth {
// verbosity: 0 = info, >0 = debug/trace, <0 = warnings only / errors only.
void configure_logging(int verbosity);
}  // namespace ppsynth
