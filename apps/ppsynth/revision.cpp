// The project revision (git describe at configure time), named in every run directory and report.
#include "apps/ppsynth/command.hpp"

namespace ppsynth::app {
const char* revision() { return PPSYNTH_REVISION; }
}  // namespace ppsynth::app
