#pragma once
// The wall time of a whole run: the seconds this segment has run, plus those of the
// segments before it that a restart joins (counted in the checkpoint it continues from).
// It goes into the diagnostics rows, the checkpoints and the stage-time table.
// This header includes no Kokkos header.
#include <chrono>

namespace rouleau {

class RunClock {
 public:
  using Clock = std::chrono::steady_clock;

  // `segment_start`: when this process began the run; `earlier_seconds`: the wall time of
  // the segments before it (0 for a new run).
  RunClock(Clock::time_point segment_start, double earlier_seconds)
      : segment_start_(segment_start), earlier_seconds_(earlier_seconds) {}

  // Seconds since the run started, over all its segments.
  double seconds() const {
    return earlier_seconds_ + std::chrono::duration<double>(Clock::now() - segment_start_).count();
  }

 private:
  Clock::time_point segment_start_;
  double earlier_seconds_;
};

}  // namespace rouleau
