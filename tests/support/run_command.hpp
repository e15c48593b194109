#pragma once
// Test support: runs a built binary (`ppsynth`, the library example) as a user would and keeps
// what it printed.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <sys/wait.h>

namespace ppsynth::test {

struct CommandResult {
  int status = -1;     // exit code; 128 + N when killed by signal N
  std::string output;  // stdout and stderr together
};

// `args` is passed to the shell after the binary; `prefix` goes before it (e.g. "cd DIR &&",
// "PPSYNTH_THREADS=x").
inline CommandResult run_program(const std::string& binary, const std::string& args, const std::string& prefix = "") {
  const std::string cmd = prefix + " " + binary + " " + args + " 2>&1";
  CommandResult r;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  for (size_t n; (n = fread(buf.data(), 1, buf.size(), p)) > 0;) r.output.append(buf.data(), n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  return r;
}

// The ppsynth the binary tests run: this build's, or PPSYNTH_TEST_BINARY's (another build, for
// example an older commit's, to show that a test fails without the fix it guards).
inline std::string ppsynth_binary() {
  const char* other = std::getenv("PPSYNTH_TEST_BINARY");
  return other && *other ? other : PPSYNTH_BINARY;
}

inline CommandResult run_ppsynth(const std::string& args, const std::string& prefix = "") {
  return run_program(ppsynth_binary(), args, prefix);
}

}  // namespace ppsynth::test
