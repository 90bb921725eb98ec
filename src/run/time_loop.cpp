// The run's sequence of steps: the steady solve, or the transient loop with its outputs,
// checkpoints, progress line and stop signals (run/time_loop.hpp).
#include "run/time_loop.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

#include "cli/progress.hpp"
#include "util/errors.hpp"

namespace rouleau {

namespace {
// The progress line of `steps` steps to `end_time`. On a terminal the line is redrawn in
// place there, and the log gets a line every half minute; otherwise (stderr to a file) the
// lines go to both. `shown`: --no-progress hides it.
class RunProgress {
 public:
  RunProgress(const int steps, const double end_time, const bool shown, RunLog* log)
      : shown_(shown), terminal_(stderr_is_terminal()),
        line_(steps, end_time, terminal_, log && terminal_ ? log->terminal() : std::cerr) {
    if (log && terminal_ && shown_)
      logged_.emplace(steps, end_time, false, log->file(), ProgressReporter::Settings{0.1, 30.0});
  }
  void update(const int step, const double time, const FluidSolveReport& report) {
    if (shown_) line_.update(step, time, report.newton_iterations, report.gmres_iterations);
    if (logged_) logged_->update(step, time, report.newton_iterations, report.gmres_iterations);
  }
  void finish() {
    if (shown_) line_.finish();
    if (logged_) logged_->finish();
  }

 private:
  bool shown_;
  bool terminal_;
  ProgressReporter line_;
  std::optional<ProgressReporter> logged_;
};

// What the signals and the clock ask for after a step.
struct StepRequests {
  int stop_signal = 0;      // the signal that asks the run to stop, or 0
  bool checkpoint = false;  // SIGUSR1, or checkpoint.every_minutes passed
};

// Signals and clocks are each rank's: on several ranks the decisions are taken together
// (any rank's request counts), since every rank takes part in a checkpoint.
StepRequests requests_after_step(const Communicator& ranks, const CheckpointConfig& every,
                                 const double minutes_since_checkpoint) {
  StepRequests requests;
  requests.stop_signal = StopSignals::stop_requested();
  requests.checkpoint = StopSignals::take_checkpoint_request() ||
                        (every.every_minutes > 0.0 && minutes_since_checkpoint >= every.every_minutes);
  if (ranks.size() > 1) {
    requests.stop_signal = static_cast<int>(ranks.max(static_cast<double>(requests.stop_signal)));
    requests.checkpoint = ranks.max(requests.checkpoint ? 1.0 : 0.0) > 0.0;
  }
  return requests;
}
}  // namespace

TimeLoop::TimeLoop(Simulation& simulation, const RunOptions& options, const Communicator& ranks, RunLog* log,
                   const RunClock& clock, Outputs outputs)
    : simulation_(simulation), options_(options), ranks_(ranks), log_(log), clock_(clock), outputs_(outputs) {}

int TimeLoop::run(const bool restarted) {
  try {
    if (simulation_.config().time.mode != TimeMode::transient) {
      run_steady();
      return static_cast<int>(ExitCode::done);
    }
    return run_transient(restarted);
  } catch (const DivergenceError& error) {
    outputs_.diagnostics.flush();
    throw DivergenceError(std::string(error.what()) + "; last good checkpoint: " + outputs_.checkpoints.last_good() +
                          "; fields and diagnostics up to the last good step are in " + options_.output_dir);
  }
}

void TimeLoop::run_steady() {
  // One frame, the solution: the state before the solve has the same time, t = 0, and
  // ParaView's XDMF reader shows nothing of a series with two frames at one time.
  const FluidSolveReport& report = simulation_.solve_steady().fluid;
  outputs_.diagnostics.add_row(simulation_, clock_.seconds());
  outputs_.fields.write(simulation_);
  std::cerr << "steady solve: " << report.newton_iterations << " Newton, " << report.gmres_iterations
            << " GMRES iterations; residual momentum " << report.momentum_residual << ", continuity "
            << report.continuity_residual << "\n";
}

int TimeLoop::run_transient(const bool restarted) {
  const CaseConfig& config = simulation_.config();
  if (!restarted) {
    outputs_.diagnostics.add_row(simulation_, clock_.seconds());  // the state as placed, at t = 0
    outputs_.fields.write(simulation_);
    write_checkpoint();
  }
  // The run ends at the time time.end, whatever step a restart continues with: the
  // steps left are (end − t) / Δt from where it starts.
  const int first_step = simulation_.steps() + 1;
  const int steps = simulation_.steps() + static_cast<int>(std::max<long long>(
                                              0, std::llround((config.time.end - simulation_.time()) / config.time.dt)));
  RunProgress progress(steps, config.time.end, options_.progress, log_);
  for (int step = first_step; step <= steps; ++step) {
    // A diagnostics row reads the energies the step computes with its forces.
    const bool diagnostics_row = step % config.output.diagnostics_every_steps == 0 || step == steps;
    const FluidSolveReport& report = simulation_.advance(diagnostics_row).fluid;
    if (diagnostics_row) outputs_.diagnostics.add_row(simulation_, clock_.seconds());
    if (step % config.output.fields_every_steps == 0 || step == steps) outputs_.fields.write(simulation_);
    progress.update(step, simulation_.time(), report);
    const CheckpointConfig& every = config.checkpoint;
    const StepRequests requests = requests_after_step(ranks_, every, outputs_.checkpoints.minutes_since_last());
    if (requests.checkpoint || (every.every_steps > 0 && step % every.every_steps == 0) || requests.stop_signal != 0 ||
        step == steps)
      write_checkpoint();
    if (requests.stop_signal != 0 && step < steps) {
      progress.finish();
      outputs_.diagnostics.flush();
      std::cerr << "stopped by signal " << requests.stop_signal << " after step " << step << " (t = "
                << simulation_.time() << " s); checkpoint " << outputs_.checkpoints.last_path()
                << "\ncontinue with: " << options_.continue_command << " " << options_.output_dir << "\n";
      return static_cast<int>(ExitCode::interrupted);
    }
  }
  progress.finish();
  if (outputs_.checkpoints.last_step() != simulation_.steps()) write_checkpoint();
  return static_cast<int>(ExitCode::done);
}

void TimeLoop::write_checkpoint() {
  outputs_.diagnostics.flush();
  outputs_.checkpoints.write(simulation_, clock_);
}

}  // namespace rouleau
