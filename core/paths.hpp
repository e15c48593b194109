#pragma once
// Where shipped data lives. The shared data folder is `../shared` beside the checkout
// unless PPSYNTH_SHARED is set; configs name exemplars relative to it as "shared:data/...".
#include <string>

namespace ppsynth {
// Root of the checkout (compiled in), overridable by PPSYNTH_ROOT.
std::string source_root();
// The shared folder (PPSYNTH_SHARED, else <source_root>/../shared).
std::string shared_root();
// Expands "shared:rel/path" and "repo:rel/path" prefixes; other paths are returned unchanged.
std::string resolve_data_path(const std::string& path);
}  // namespace ppsynth
