#include "optim/method/method.hpp"

#include "core/config/defaults_catalog.hpp"

PPSYNTH_DEFAULTS_KIND("method", ppsynth::MethodRegistry)
