#pragma once
// SIGINT, SIGTERM and SIGHUP: the first asks the running analysis to stop at its next
// clean point, so that the results so far are written; a second ends the program at
// once, its temporary files removed.

#include <feran/core/stop.hpp>

namespace feran::app {

/// Installs the handlers (once, before the command runs).
void install_interrupt_handlers();
/// The token the analyses are given.
StopToken interrupt_token();
/// The signal that asked to stop, or 0.
int interrupt_signal();
/// "SIGINT", "SIGTERM", "SIGHUP".
const char* signal_name(int signal);

}  // namespace feran::app
