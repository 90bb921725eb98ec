#include "run/run_case.hpp"

#include "run/kokkos_session.hpp"

#include <Kokkos_Core.hpp>
#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "cells/cells_from_case.hpp"
#include "cli/progress.hpp"
#include "cli/stop_signals.hpp"
#include "config/derived.hpp"
#include "config/load_case.hpp"
#include "config/memory_estimate.hpp"
#include "config/resolved_case.hpp"
#include "fluid/fluid_solver.hpp"
#include "geometry/cell_mesh.hpp"
#include "io/atomic_file.hpp"
#include "io/provenance.hpp"
#include "io/run_folder.hpp"
#include "io/run_log.hpp"
#include "parallel/communicator.hpp"
#include "parallel/mpi_session.hpp"
#include "coupling/immersed_coupling.hpp"
#include "run/diagnostics_output.hpp"
#include "run/field_output.hpp"
#include "run/run_checkpoints.hpp"
#include "run/run_clock.hpp"
#include "run/run_diagnostics.hpp"
#include "run/run_report.hpp"
#include "config/scene_plan.hpp"
#include "run/simulation.hpp"
#include "util/stage_times.hpp"
#include "util/errors.hpp"

namespace rouleau {

namespace {

using Clock = std::chrono::steady_clock;

// The log of a run on several ranks is the first rank's: the others' std::cerr says
// nothing while this lives (an error they throw is reported after it, by the caller).
class QuietOtherRanks {
 public:
  explicit QuietOtherRanks(const Communicator& ranks) {
    if (ranks.rank() > 0) saved_ = std::cerr.rdbuf(nullptr);
  }
  ~QuietOtherRanks() {
    if (saved_) {
      std::cerr.rdbuf(saved_);
      std::cerr.clear();
    }
  }
  QuietOtherRanks(const QuietOtherRanks&) = delete;
  QuietOtherRanks& operator=(const QuietOtherRanks&) = delete;

 private:
  std::streambuf* saved_ = nullptr;
};

// The run itself, once its folder is ready: builds the simulation, runs the time loop and
// writes the outputs into options.output_dir (`log` is the first rank's, null on the others).
int run_in_folder(const CaseConfig& config, const RunOptions& options, const DerivedQuantities& derived,
                  const Communicator& ranks, const std::string& run_id, RunLog* log, Clock::time_point run_start) {
  const bool writes_files = ranks.rank() == 0;
  const std::string out = options.output_dir;
  const FoundCheckpoint* restart = options.restart.get();
  // The log's first lines: what ran, how, and where.
  report_run_opening(config, out);

  Simulation simulation(config, default_mesh_cache_dir(), &ranks);
  const CaseCells& cells = simulation.cells();
  const MemoryEstimate memory = estimate_memory(config, Kokkos::DefaultHostExecutionSpace().concurrency());
  report_run_setup(simulation, derived, ranks, memory);

  std::vector<MeshDescription> meshes = output_meshes(simulation);
  const MeshDescription& fluid_mesh = meshes.front();
  std::vector<std::pair<std::string, std::string>> provenance_entries{
      {"case", config.name},
      {"run_id", run_id},
      {"execution_space", Kokkos::DefaultExecutionSpace::name()},
      {"threads", std::to_string(Kokkos::DefaultHostExecutionSpace().concurrency())},
      {"ranks", std::to_string(ranks.size())},
      {"fluid_mesh_hash", hash_mesh(fluid_mesh.coordinates.data(), fluid_mesh.coordinates.size(),
                                    fluid_mesh.connectivity.data(), fluid_mesh.connectivity.size())}};
  for (const auto& [kind, cell_mesh] : cells.meshes) provenance_entries.emplace_back("cell_mesh_hash_" + kind, cell_mesh.hash);
  const Provenance provenance = build_provenance(provenance_entries);
  const std::map<std::string, std::string> mesh_hashes = mesh_hash_labels(provenance_entries);
  // The volume drift is measured from the cells as placed: before a restart moves them.
  CellDiagnostics cell_diagnostics(cells, config, &ranks);
  if (restart) restart_simulation(simulation, *restart, mesh_hashes, out, writes_files);
  // What a run that ran this far wrote after the checkpoint is dropped: the diagnostics
  // rows and the field steps of later steps.
  const auto earlier_rows = earlier_diagnostics_rows(out, restart, writes_files);
  FieldOutput fields(simulation, ranks, std::move(meshes), provenance, out, restart, writes_files);

  DiagnosticsOutput diagnostics(simulation, std::move(cell_diagnostics), out, earlier_rows, writes_files);
  const RunClock clock(run_start, restart ? restart->data.wall_seconds : 0.0);

  // Checkpoints (transient runs): at the start, every N steps or M minutes, on request
  // (SIGUSR1), on a stop signal and at the end.
  const bool transient = config.time.mode == TimeMode::transient;
  RunCheckpoints checkpoints(config, derived, out, restart, provenance, mesh_hashes, run_id, writes_files);
  // The diagnostics on disk go first: a run killed after the checkpoint then has every
  // row up to it (the restart keeps those and drops later ones).
  auto write_checkpoint = [&] {
    diagnostics.flush();
    checkpoints.write(simulation, clock);
  };

  StopSignals signals;
  try {
    if (!transient) {
      fields.write(simulation);
      const FluidSolveReport& report = simulation.solve_steady().fluid;
      diagnostics.add_row(simulation, clock.seconds());
      fields.write(simulation);
      std::cerr << "steady solve: " << report.newton_iterations << " Newton, " << report.gmres_iterations
                << " GMRES iterations; residual momentum " << report.momentum_residual << ", continuity "
                << report.continuity_residual << "\n";
    } else {
      if (!restart) {
        diagnostics.add_row(simulation, clock.seconds());  // the state as placed, at t = 0
        fields.write(simulation);
        write_checkpoint();
      }
      // The run ends at the time time.end, whatever step a restart continues with: the
      // steps left are (end − t) / Δt from where it starts.
      const int first_step = simulation.steps() + 1;
      const int steps = simulation.steps() + static_cast<int>(std::max<long long>(
                                                 0, std::llround((config.time.end - simulation.time()) / config.time.dt)));
      // On a terminal the line is redrawn in place there, and the log gets a line every
      // half minute; otherwise (stderr to a file) the lines go to both.
      const bool terminal = stderr_is_terminal();
      ProgressReporter progress(steps, config.time.end, terminal, log && terminal ? log->terminal() : std::cerr);
      std::optional<ProgressReporter> logged_progress;
      if (log && terminal && options.progress)
        logged_progress.emplace(steps, config.time.end, false, log->file(), ProgressReporter::Settings{0.1, 30.0});
      for (int step = first_step; step <= steps; ++step) {
        // A diagnostics row reads the energies the step computes with its forces.
        const bool diagnostics_row = step % config.output.diagnostics_every_steps == 0 || step == steps;
        const FluidSolveReport& report = simulation.advance(diagnostics_row).fluid;
        if (diagnostics_row) diagnostics.add_row(simulation, clock.seconds());
        if (step % config.output.fields_every_steps == 0 || step == steps) fields.write(simulation);
        if (options.progress)
          progress.update(step, simulation.time(), report.newton_iterations, report.gmres_iterations);
        if (logged_progress)
          logged_progress->update(step, simulation.time(), report.newton_iterations, report.gmres_iterations);
        const CheckpointConfig& every = config.checkpoint;
        const double minutes = checkpoints.minutes_since_last();
        // Signals and clocks are each rank's: on several ranks the decisions are taken
        // together (any rank's request counts), since every rank takes part in a checkpoint.
        int signal_number = StopSignals::stop_requested();
        bool checkpoint_now = StopSignals::take_checkpoint_request() ||
                              (every.every_minutes > 0.0 && minutes >= every.every_minutes);
        if (ranks.size() > 1) {
          signal_number = static_cast<int>(ranks.max(static_cast<double>(signal_number)));
          checkpoint_now = ranks.max(checkpoint_now ? 1.0 : 0.0) > 0.0;
        }
        if (checkpoint_now || (every.every_steps > 0 && step % every.every_steps == 0) || signal_number != 0 ||
            step == steps)
          write_checkpoint();
        if (signal_number != 0 && step < steps) {
          if (options.progress) progress.finish();
          if (logged_progress) logged_progress->finish();
          diagnostics.flush();
          std::cerr << "stopped by signal " << signal_number << " after step " << step << " (t = " << simulation.time()
                    << " s); checkpoint " << checkpoints.last_path() << "\ncontinue with: " << options.continue_command << " "
                    << out << "\n";
          return static_cast<int>(ExitCode::interrupted);
        }
      }
      if (options.progress) progress.finish();
      if (logged_progress) logged_progress->finish();
      if (checkpoints.last_step() != simulation.steps()) write_checkpoint();
    }
  } catch (const DivergenceError& error) {
    diagnostics.flush();
    throw DivergenceError(std::string(error.what()) + "; last good checkpoint: " + checkpoints.last_good() +
                          "; fields and diagnostics up to the last good step are in " + out);
  }
  diagnostics.flush();
  ranks.barrier();  // the files are complete before any rank returns (case drivers read them)
  report_run_end(simulation, ranks, clock.seconds(), memory, out, fields.mesh_xdmf_paths());
  return static_cast<int>(ExitCode::done);
}

}  // namespace

int run_case(const CaseConfig& config, const RunOptions& options) {
  const auto run_start = Clock::now();
  // Under mpirun the fluid is split across the ranks; the first rank writes every file.
  const Communicator ranks = Communicator::world();
  const bool writes_files = ranks.rank() == 0;
  const QuietOtherRanks quiet(ranks);
  const DerivedQuantities derived = derive_quantities(config);
  if (options.explain) {
    if (writes_files) std::cout << describe_scene(config, derived, plan_scene(config, derived));
    return static_cast<int>(ExitCode::done);
  }
  const std::string out = options.output_dir;
  const FoundCheckpoint* restart = options.restart.get();
  // A run keeps its id over the segments a restart joins; every file it writes carries it.
  const std::string run_id = restart ? restart->data.labels.count("run_id") ? restart->data.labels.at("run_id") : ""
                                     : new_run_id();
  std::optional<RunLog> log;
  if (writes_files) {
    if (!restart) prepare_new_run_folder(out, options.overwrite);
    const std::string now = current_utc_time_iso8601();
    try {
      log.emplace(out + "/" + run_log_name,
                  run_log_first_line(run_id, restart ? "continued from " + restart->path + " at " + now
                                                     : "case " + config.name + ", started " + now),
                  restart != nullptr);
    } catch (const std::runtime_error& error) {
      throw InputError(out, restart ? "--restart" : "--out", error.what());
    }
  }
  // The run's log ends with what stopped it (the caller reports it on stderr, after the log is closed).
  try {
    if (writes_files) write_file_atomically(out + "/case.resolved.toml", resolved_case_toml(config, derived));
    return run_in_folder(config, options, derived, ranks, run_id, log ? &*log : nullptr, run_start);
  } catch (const std::exception& error) {
    if (log) log->file() << "rouleau: the run stopped: " << error.what() << std::endl;
    throw;
  }
}

CaseDriverRun run_case_driver(int argc, char** argv, const std::string& default_case,
                              const std::string& default_output_dir) {
  CaseDriverRun run;
  const CommandLine command_line =
      parse_driver_command_line(argc, argv, default_case, default_output_dir, std::cout, std::cerr);
  if (command_line.command != Command::run) {  // --help or a usage error
    run.status = command_line.exit_code;
    return run;
  }
  run.options = run_options(command_line);
  if (argc > 0) run.options.continue_command = std::string(argv[0]) + " --restart";
  run.status = run_reporting_errors(
      [&] {
        // The whole case is validated before Kokkos starts, as `rouleau run` does.
        run.config = load_run_case(command_line, run.options.restart, std::cerr);
        derive_quantities(run.config);
        check_memory(run.config, command_line);  // a case that does not fit stops here
        const MpiSession mpi;  // before Kokkos; several ranks under mpirun
        const KokkosSession kokkos(argc > 0 ? argv[0] : "case", command_line.threads);
        return run_case(run.config, run.options);
      },
      std::cerr);
  run.ran = run.status == 0 && !run.options.explain;
  return run;
}

}  // namespace rouleau
