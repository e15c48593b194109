#pragma once
// Test support: the built `ppsynth` as a child process whose output is read line by line,
// so a test can signal it at a chosen point of its progress (interrupt and resume tests).
#include <csignal>
#include <cstdio>
#include <functional>
#include <string>

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tests/support/run_command.hpp"

namespace ppsynth::test {

class Child {
 public:
  // Runs `ppsynth args` (run_command.hpp: this build's, or PPSYNTH_TEST_BINARY) through the shell, exec'd (the pid is the binary's),
  // stdout and stderr into one pipe. `env`: assignments for its environment ("PPSYNTH_THREADS=1"),
  // set through env(1), which execs the binary in its place (the pid stays the binary's).
  explicit Child(const std::string& args, const std::string& env = "") {
    int fds[2];
    if (::pipe(fds) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(fds[1], 1);
      ::dup2(fds[1], 2);
      ::close(fds[0]);
      ::close(fds[1]);
      const std::string cmd = "exec " + (env.empty() ? "" : "env " + env + " ") + ppsynth_binary() + " " + args;
      ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    out_ = ::fdopen(fds[0], "r");
  }
  ~Child() {
    if (pid_ > 0 && status_ < 0) {
      ::kill(pid_, SIGKILL);
      finish();
    }
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  // Reads lines until one satisfies `match` (true) or the output ends (false).
  bool wait_for(const std::function<bool(const std::string&)>& match) {
    for (std::string line; read_line(line);)
      if (match(line)) return true;
    return false;
  }
  void signal(int sig) { ::kill(pid_, sig); }
  // Reads the rest of the output and waits: the exit code, or 128 + the signal's number.
  int finish() {
    for (std::string line; read_line(line);) {
    }
    if (out_) ::fclose(out_), out_ = nullptr;
    int st = 0;
    ::waitpid(pid_, &st, 0);
    status_ = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
    return status_;
  }
  const std::string& output() const { return all_; }

 private:
  bool read_line(std::string& line) {
    line.clear();
    if (!out_) return false;
    for (int c; (c = std::fgetc(out_)) != EOF;) {
      all_ += static_cast<char>(c);
      if (c == '\n') return true;
      line += static_cast<char>(c);
    }
    return !line.empty();
  }
  pid_t pid_ = -1;
  FILE* out_ = nullptr;
  int status_ = -1;
  std::string all_;
};

}  // namespace ppsynth::test
