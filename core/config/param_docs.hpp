#pragma once
// The doc line of each declared parameter (core/config/params.hpp) for the generated reference
// (core/config/reference_markdown.hpp), by the kind and part whose defaults hold it: the
// "gabor" method's own keys and each of its stage kinds' blocks add theirs under
// ("method", "gabor"). Nested blocks are nested objects of lines, as the defaults are.
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {
bool register_param_docs(const std::string& kind, const std::string& part, std::function<nlohmann::json()> docs);
// Every registration of the part merged; an empty object when none.
nlohmann::json param_docs(const std::string& kind, const std::string& part);
}  // namespace ppsynth

// PPSYNTH_PARAM_DOCS("method", "gabor", [] { return GaborOptions::params().docs(); }) in a .cpp.
#define PPSYNTH_PARAM_DOCS(KIND, PART, ...)                                                        \
  namespace {                                                                                      \
  [[maybe_unused]] const bool PPSYNTH_PARAM_DOCS_CONCAT(ppsynth_param_docs_, __LINE__) =           \
      ::ppsynth::register_param_docs(KIND, PART, __VA_ARGS__);                                     \
  }
#define PPSYNTH_PARAM_DOCS_CONCAT_INNER(a, b) a##b
#define PPSYNTH_PARAM_DOCS_CONCAT(a, b) PPSYNTH_PARAM_DOCS_CONCAT_INNER(a, b)
