#include "apps/ppsynth/stop_signals.hpp"

#include <csignal>

namespace ppsynth::app {

namespace {

std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_signal = 0;

extern "C" void request_stop(int sig) {
  g_signal = sig;
  g_stop = true;
}

}  // namespace

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = request_stop;
  sa.sa_flags = SA_RESETHAND;  // no SA_RESTART: a blocking wait returns EINTR and sees the flag
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

const std::atomic<bool>* stop_flag() { return &g_stop; }
int stop_signal() { return g_signal; }
const char* stop_signal_name() { return g_signal == SIGTERM ? "SIGTERM" : "SIGINT"; }
int exit_code_for_stop() { return 128 + (g_signal == SIGTERM ? SIGTERM : SIGINT); }

}  // namespace ppsynth::app
