#pragma once
// Test support shared by the test files that write files: a fresh directory per test.
#include <filesystem>
#include <string>

namespace ppsynth::test {

// <system temp>/ppsynth_test_<name>, emptied first so a test never reads an earlier run's files.
inline std::filesystem::path scratch_dir(const std::string& name) {
  auto d = std::filesystem::temp_directory_path() / ("ppsynth_test_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace ppsynth::test
