// Simulated crashes for tests of crash handling: the signal's default action, so that a
// sanitizer's own handler (ASan turns SIGSEGV into a report and exit status 1) does not change
// how the process ends.
#pragma once

#include <csignal>
#include <cstdlib>

namespace sagrid::test {

[[noreturn]] inline void dieBySignal(int signal) {
  std::signal(signal, SIG_DFL);
  std::raise(signal);
  std::_Exit(128 + signal);  // not reached: the default action ends the process
}

}  // namespace sagrid::test
