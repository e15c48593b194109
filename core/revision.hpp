#pragma once
// The project revision (git describe, refreshed at every build by scripts/write_revision.cmake),
// named in every run directory and report and by `ppsynth --version`.
namespace ppsynth {
const char* revision();
}  // namespace ppsynth
