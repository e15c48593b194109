// The map terms' registry and its entry in `ppsynth config --defaults`.
#include "optim/gabor/map_term.hpp"

#include "core/config/defaults_catalog.hpp"

namespace ppsynth {

void check_map_terms_in_windows(const nlohmann::json& terms) {
  for (const auto& t : create_map_terms(terms))
    if (!t.term->in_windows())
      throw config_error("method.map_terms." + t.name, "works on the paper's u x u outputs only, not on a rectangle "
                                                       "output's windows (\"output\"); \"class_own\" works on both");
}

}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("map_term", ppsynth::MapTermRegistry)
