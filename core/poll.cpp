#include "core/poll.hpp"

namespace ppsynth {

namespace {
// Per thread: a computation polls on the thread its caller installed the check on.
thread_local const std::function<void()>* current = nullptr;
}  // namespace

PollScope::PollScope(std::function<void()> check) : check_(std::move(check)), outer_(current) { current = &check_; }

PollScope::~PollScope() { current = outer_; }

void poll() {
  if (current) (*current)();
}

}  // namespace ppsynth
