// The map terms' registry and its entry in `ppsynth config --defaults`.
#include "optim/gabor/stages/map_term.hpp"

#include "core/config/defaults_catalog.hpp"

PPSYNTH_DEFAULTS_KIND("map_term", ppsynth::MapTermRegistry)
