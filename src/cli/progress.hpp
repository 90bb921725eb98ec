#pragma once
// The progress line of a run: step, simulated time, speed, solver iterations and ETA.
// Host-only: includes no Kokkos header.
#include <functional>
#include <iosfwd>
#include <string>

namespace rouleau {

// True when stderr is a terminal (then the progress line is redrawn in place).
bool stderr_is_terminal();

// Seconds on a monotonic clock.
double monotonic_seconds();

// Shows the progress of a time loop. On a terminal one line is redrawn in place
// ('\r' + clear to end of line) at most every `terminal_interval_s`; otherwise (a log file)
// a full line is printed at most every `log_interval_s`. The clock is injectable for tests.
class ProgressReporter {
 public:
  struct Settings {
    double terminal_interval_s = 0.1;
    double log_interval_s = 5.0;
    std::function<double()> clock = monotonic_seconds;
  };

  // `total_steps` and `end_time` [s] of the run; `terminal`: redraw in place on `out`.
  ProgressReporter(int total_steps, double end_time, bool terminal, std::ostream& out);
  ProgressReporter(int total_steps, double end_time, bool terminal, std::ostream& out, Settings settings);

  // Step `step` (1-based) reached simulated time `time` [s] with these solver iteration
  // counts; shown unless the previous line was shown less than an interval ago.
  void update(int step, double time, int newton_iterations, int gmres_iterations);

  // Shows the last state if it was not shown, and ends the line. Idempotent.
  void finish();

  // The text of the line for a state (no '\r', no newline).
  std::string line(int step, double time, int newton_iterations, int gmres_iterations) const;

 private:
  void show(const std::string& text);

  int total_steps_;
  double end_time_;
  bool terminal_;
  std::ostream& out_;
  Settings settings_;
  double start_s_;
  double last_shown_s_ = 0.0;
  bool shown_any_ = false;
  bool line_open_ = false;     // a terminal line without its newline yet
  std::string pending_line_;   // the last state, when it was not shown
  bool finished_ = false;
};

}  // namespace rouleau
