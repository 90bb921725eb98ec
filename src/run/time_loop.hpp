#pragma once
// The run's sequence of steps, the same at every step (as LAMMPS' Verlet::run calls its
// hooks): a steady solve with the fields before and after it, or the transient loop from the
// first step (or the step after the checkpoint a restart continues from) to time.end. After
// each step it adds a diagnostics row, writes the fields and shows the progress line at
// their intervals, and writes a checkpoint: at the start, every checkpoint.every_steps steps
// or every_minutes minutes, on request (SIGUSR1), on a stop signal and at the end. SIGINT or
// SIGTERM ends the loop after the current step (cli/stop_signals.hpp).
#include "io/run_log.hpp"
#include "cli/stop_signals.hpp"
#include "parallel/communicator.hpp"
#include "run/diagnostics_output.hpp"
#include "run/field_output.hpp"
#include "run/run_case.hpp"
#include "run/run_checkpoints.hpp"
#include "run/run_clock.hpp"
#include "run/simulation.hpp"

namespace rouleau {

class TimeLoop {
 public:
  // What the loop writes: the diagnostics rows, the fields and the checkpoints.
  struct Outputs {
    DiagnosticsOutput& diagnostics;
    FieldOutput& fields;
    RunCheckpoints& checkpoints;
  };

  // Installs the stop signals' handlers for its lifetime. `log`: the first rank's run log,
  // null on the others. Everything it is given must outlive it.
  TimeLoop(Simulation& simulation, const RunOptions& options, const Communicator& ranks, RunLog* log,
           const RunClock& clock, Outputs outputs);

  // Runs the case to its end; `restarted`: it continues from a checkpoint (whose step's row,
  // fields and checkpoint are written already). Returns ExitCode::done, or
  // ExitCode::interrupted when a stop signal ended it early (the diagnostics flushed, a
  // checkpoint written and the command that continues the run said). Throws DivergenceError
  // naming the last good checkpoint and where the outputs are.
  int run(bool restarted);

 private:
  void run_steady();
  int run_transient(bool restarted);
  // The diagnostics on disk go first: a run killed after the checkpoint then has every row
  // up to it (the restart keeps those and drops later ones).
  void write_checkpoint();

  Simulation& simulation_;
  const RunOptions& options_;
  const Communicator& ranks_;
  RunLog* log_;
  const RunClock& clock_;
  Outputs outputs_;
  StopSignals signals_;
};

}  // namespace rouleau
