#pragma once
// Every config key of every registered part as Markdown: the generated half of the reference
// (docs/reference_generated.md, written by `ppsynth config --markdown`). It is made from the
// same catalog as `ppsynth config --defaults` (core/config/defaults_catalog.hpp), so the page
// says what the registries hold; a test fails when the committed page differs.
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

// `catalog`: kind -> part name -> {"description", "defaults", "bounds"} (or, for a kind whose
// parts are config fragments such as presets, any other object, shown as JSON).
std::string config_reference_markdown(const nlohmann::json& catalog);

}  // namespace ppsynth
