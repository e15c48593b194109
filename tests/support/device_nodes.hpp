#pragma once
// Test support: character devices inside a scratch directory, so tests of "never replace a
// device" write to a copy of /dev/full or /dev/null (same major/minor) and a regression can
// only replace the copy, never the machine's own /dev nodes (the suite runs as root in CI).
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <optional>
#include <string>

namespace ppsynth::test {

// dir/name as the character device major:minor; nullopt where mknod is not permitted.
inline std::optional<std::string> scratch_char_device(const std::filesystem::path& dir, const std::string& name,
                                                      unsigned major, unsigned minor) {
  const std::string path = (dir / name).string();
  if (::mknod(path.c_str(), S_IFCHR | 0666, makedev(major, minor)) != 0) return std::nullopt;
  return path;
}

inline std::optional<std::string> scratch_dev_full(const std::filesystem::path& dir) {
  return scratch_char_device(dir, "full", 1, 7);
}
inline std::optional<std::string> scratch_dev_null(const std::filesystem::path& dir) {
  return scratch_char_device(dir, "null", 1, 3);
}

}  // namespace ppsynth::test
