#pragma once
// A long computation's stop check, for a caller that must answer an interrupt while it runs
// (the Python binding's Ctrl-C, python/src/bind_evaluation.cpp). The computation calls poll()
// between steps of a few milliseconds at most; a PollScope on the same thread installs the
// check, which may throw to end the computation (the exception leaves it like any error).
// Without a scope poll() does nothing: the CLI's SIGINT ends the process anyway.
#include <functional>

namespace ppsynth {

class PollScope {
 public:
  explicit PollScope(std::function<void()> check);
  ~PollScope();  // restores the scope it replaced (scopes nest)
  PollScope(const PollScope&) = delete;
  PollScope& operator=(const PollScope&) = delete;

 private:
  std::function<void()> check_;
  const std::function<void()>* outer_;
};

// Runs the current thread's check, if any.
void poll();

}  // namespace ppsynth
