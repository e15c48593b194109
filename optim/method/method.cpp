#include "optim/method/method.hpp"

#include "core/config/defaults_catalog.hpp"
#include "core/error.hpp"

namespace ppsynth {

void check_initialization_inside(const PointSet& init, const Domain& area, const std::string& method,
                                 const std::string& area_name) {
  for (size_t i = 0; i < init.size(); ++i)
    if (!area.contains(init[i]))
      throw InputError(method + ": the initialization's point " + std::to_string(i + 1) + " (" + std::to_string(init[i].x) +
                       ", " + std::to_string(init[i].y) + ") lies outside " + area_name + " [" + std::to_string(area.x0) +
                       ", " + std::to_string(area.x1) + "] x [" + std::to_string(area.y0) + ", " + std::to_string(area.y1) + "]");
}

}  // namespace ppsynth

PPSYNTH_DEFAULTS_KIND("method", ppsynth::MethodRegistry)
