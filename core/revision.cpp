#include "core/revision.hpp"

#include "ppsynth_revision.h"  // generated into the build tree at every build

namespace ppsynth {
const char* revision() { return PPSYNTH_REVISION; }
}  // namespace ppsynth
