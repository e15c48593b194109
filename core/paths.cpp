#include "core/paths.hpp"

#include <cstdlib>
#include <filesystem>

#ifndef PPSYNTH_SOURCE_ROOT
#define PPSYNTH_SOURCE_ROOT "."
#endif

namespace ppsynth {

std::string source_root() {
  if (const char* e = std::getenv("PPSYNTH_ROOT")) return e;
  return PPSYNTH_SOURCE_ROOT;
}

std::string shared_root() {
  if (const char* e = std::getenv("PPSYNTH_SHARED")) return e;
  return (std::filesystem::path(source_root()) / ".." / "shared").lexically_normal().string();
}

std::string resolve_data_path(const std::string& path) {
  auto strip = [&](const std::string& prefix) { return path.substr(prefix.size()); };
  if (path.rfind("shared:", 0) == 0) return (std::filesystem::path(shared_root()) / strip("shared:")).string();
  if (path.rfind("repo:", 0) == 0) return (std::filesystem::path(source_root()) / strip("repo:")).string();
  return path;
}

}  // namespace ppsynth
