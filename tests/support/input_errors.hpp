#pragma once
// Test support for "bad input gets a clear error": a file written for a test, and the checks
// that a call throws an InputError (nothing else, and not nothing) whose message says what the
// user needs: every fragment, and for a point file the file and line.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/error.hpp"

namespace ppsynth::test {

// `text` written as dir/name, byte for byte; returns its path.
inline std::string write_file(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  const std::string p = (dir / name).string();
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// Runs `f`; requires an InputError whose message holds every fragment.
template <class F>
void require_input_error(F&& f, const std::vector<std::string>& fragments) {
  try {
    f();
    FAIL_CHECK("no InputError");
  } catch (const InputError& e) {
    const std::string msg = e.what();
    INFO(msg);
    for (const auto& fr : fragments) CHECK(msg.find(fr) != std::string::npos);
  }
}

// The same, and the message names `file` where the input went wrong: "file:line:" for
// line > 0, "file:" for line 0 (the file as a whole).
template <class F>
void require_located(F&& f, const std::string& file, long line, std::vector<std::string> fragments = {}) {
  fragments.push_back(line > 0 ? file + ":" + std::to_string(line) + ":" : file + ":");
  INFO("the input: " << file);
  require_input_error(std::forward<F>(f), fragments);
}

}  // namespace ppsynth::test
