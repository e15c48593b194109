// The point terms' registry and its entry in `ppsynth config --defaults`.
#include "optim/terms/point_term.hpp"

#include "core/config/defaults_catalog.hpp"

PPSYNTH_DEFAULTS_KIND("point_term", ppsynth::PointTermRegistry)
