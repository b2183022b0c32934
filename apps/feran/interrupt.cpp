#include "interrupt.hpp"

#include <atomic>
#include <csignal>

#include <feran/io/output_files.hpp>

namespace feran::app {

namespace {

std::atomic<bool> stop_requested{false};
std::atomic<int> stop_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "the handler may only touch lock-free atomics");

extern "C" void on_signal(int signal) {
  if (!stop_requested.exchange(true)) {
    stop_signal.store(signal);
    return;
  }
  // A second signal: the user does not want to wait for the clean point.
  remove_temporary_outputs();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads and writes go on; the analyses look at the flag
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaction(s, &action, nullptr);
}

StopToken interrupt_token() { return StopToken(stop_requested); }

int interrupt_signal() { return stop_signal.load(); }

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

}  // namespace feran::app
