#include "cli/stop_signals.hpp"

#include <unistd.h>

#include <csignal>
#include <stdexcept>

namespace rouleau {

namespace {

volatile std::sig_atomic_t stop_signal = 0;
volatile std::sig_atomic_t checkpoint_request = 0;
bool installed = false;
struct sigaction previous_interrupt, previous_terminate, previous_user1;

// Async-signal-safe: sets a flag, or ends the process at once on a second stop signal.
extern "C" void on_stop_signal(int signal_number) {
  if (stop_signal != 0) {
    // Every file is written to a temporary name and renamed: none is left half-written.
    static const char message[] = "rouleau: second stop signal: exiting at once, without a new checkpoint\n";
    const ssize_t ignored = write(STDERR_FILENO, message, sizeof message - 1);
    (void)ignored;
    _exit(128 + signal_number);
  }
  stop_signal = signal_number;
}

extern "C" void on_checkpoint_signal(int) { checkpoint_request = 1; }

void install(int signal_number, void (*handler)(int), struct sigaction* previous) {
  struct sigaction action = {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // system calls under way (file writes) resume
  sigaction(signal_number, &action, previous);
}

}  // namespace

StopSignals::StopSignals() {
  if (installed) throw std::logic_error("rouleau::StopSignals: already installed");
  installed = true;
  stop_signal = 0;
  checkpoint_request = 0;
  install(SIGINT, on_stop_signal, &previous_interrupt);
  install(SIGTERM, on_stop_signal, &previous_terminate);
  install(SIGUSR1, on_checkpoint_signal, &previous_user1);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &previous_interrupt, nullptr);
  sigaction(SIGTERM, &previous_terminate, nullptr);
  sigaction(SIGUSR1, &previous_user1, nullptr);
  installed = false;
}

int StopSignals::stop_requested() { return stop_signal; }

bool StopSignals::take_checkpoint_request() {
  if (checkpoint_request == 0) return false;
  checkpoint_request = 0;
  return true;
}

}  // namespace rouleau
