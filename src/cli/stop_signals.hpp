#pragma once
// Stopping a long run cleanly on a signal (docs/running.md, "Signals"):
//   SIGINT, SIGTERM  the first asks the time loop to finish the current step, write a
//                    checkpoint and exit with ExitCode::interrupted (4); a second one ends
//                    the process at once with 128 + the signal's number (every file is
//                    written to a temporary name and renamed, so none is left half-written);
//   SIGUSR1          asks for a checkpoint after the current step; the run goes on.
// Host-only: includes no Kokkos header.

namespace rouleau {

// Installs the handlers for its lifetime (the previous ones come back afterwards) and
// clears any earlier request. One at a time.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal that asked the run to stop (SIGINT or SIGTERM), or 0.
  static int stop_requested();
  // Whether a checkpoint was asked for (SIGUSR1) since the last call; clears the request.
  static bool take_checkpoint_request();
};

}  // namespace rouleau
