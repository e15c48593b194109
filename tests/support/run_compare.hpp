#pragma once
// Test support: two run directories hold the same run, file by file and byte for byte
// (run.json's wall times and the marker aside; loss.csv without its seconds column).
#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>
#include <string>

#include "core/formats/text_table.hpp"

namespace ppsynth::test {

namespace fs = std::filesystem;

// loss.csv without the wall-time column.
inline std::string losses_without_seconds(const fs::path& csv) {
  return std::regex_replace(ppsynth::read_file_text(csv.string()), std::regex(",[^,\n]*\n"), "\n");
}

// Every file of `a` equals `b`'s (run.json and the marker aside; loss.csv without seconds).
inline void check_same_run(const fs::path& a, const fs::path& b) {
  size_t compared = 0;
  for (auto& e : fs::recursive_directory_iterator(a)) {
    if (!e.is_regular_file()) continue;
    const fs::path rel = fs::relative(e.path(), a);
    const std::string name = rel.filename().string();
    if (name == "run.json" || name == ".ppsynth-run") continue;
    INFO(rel.string());
    REQUIRE(fs::exists(b / rel));
    if (name == "loss.csv") CHECK(losses_without_seconds(e.path()) == losses_without_seconds(b / rel));
    else CHECK(ppsynth::read_file_text(e.path().string()) == ppsynth::read_file_text((b / rel).string()));
    ++compared;
  }
  CHECK(compared >= 10);
  CHECK_FALSE(fs::exists(b / "checkpoint.bin"));  // a finished run keeps no checkpoint
}

}  // namespace ppsynth::test
