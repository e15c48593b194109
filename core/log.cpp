#include "core/log.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>

namespace ppsynth {

void configure_logging(int verbosity) {
  // Logs go to stderr so stdout stays clean for data (`ppsynth eval --json`).
  static auto logger = [] {
    auto l = spdlog::stderr_color_mt("ppsynth");
    spdlog::set_default_logger(l);
    return l;
  }();
  spdlog::level::level_enum lvl = spdlog::level::info;
  if (verbosity >= 2) lvl = spdlog::level::trace;
  else if (verbosity == 1) lvl = spdlog::level::debug;
  else if (verbosity == -1) lvl = spdlog::level::warn;
  else if (verbosity <= -2) lvl = spdlog::level::err;
  logger->set_level(lvl);
  logger->set_pattern("[%H:%M:%S] %^%l%$ %v");
}

}  // namespace ppsynth
