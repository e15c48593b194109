// The point terms' registry and its entry in `ppsynth config --defaults`.
#include "optim/terms/point_term.hpp"

#include "core/config/defaults_catalog.hpp"

namespace ppsynth {

void check_point_terms_in_windows(const nlohmann::json& terms) {
  for (const auto& t : create_point_terms(terms))
    if (!t.term->in_windows())
      throw config_error("method.terms." + t.name, "works on the paper's u x u outputs only, not on a rectangle "
                                                   "output's windows (\"output\"); \"separation\" works on both");
}

}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("point_term", ppsynth::PointTermRegistry)
