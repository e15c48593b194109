#pragma once
// The catalog behind `ppsynth config --defaults`: each registry adds itself under its
// kind name ("loss", "rasterizer", ...) so one command prints every default of the project.
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace ppsynth {
bool register_defaults_kind(const std::string& kind, std::function<nlohmann::json()> describe);
nlohmann::json defaults_catalog();
}  // namespace ppsynth

// PPSYNTH_DEFAULTS_KIND("loss", LossRegistry) in one .cpp per registry.
#define PPSYNTH_DEFAULTS_KIND(KIND, REG)                                                          \
  namespace {                                                                                      \
  [[maybe_unused]] const bool ppsynth_kind_registered =                                            \
      ::ppsynth::register_defaults_kind(KIND, [] { return REG::instance().describe(); });         \
  }
