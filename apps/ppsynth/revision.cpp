// The project revision (git describe, refreshed at every build by scripts/write_revision.cmake),
// named in every run directory and report.
#include "apps/ppsynth/command.hpp"
#include "ppsynth_revision.h"

namespace ppsynth::app {
const char* revision() { return PPSYNTH_REVISION; }
}  // namespace ppsynth::app
