// Running a case: the run's folder and log, the pieces a run is made of (the simulation,
// its outputs, its checkpoints) put together in order, the time loop run, and the report at
// its end; and the same for a case driver's command line.
#include "run/run_case.hpp"

#include <chrono>
#include <iostream>
#include <optional>

#include <Kokkos_Core.hpp>

#include "config/derived.hpp"
#include "config/memory_estimate.hpp"
#include "config/resolved_case.hpp"
#include "config/scene_plan.hpp"
#include "geometry/mesh_cache.hpp"
#include "io/atomic_file.hpp"
#include "io/provenance.hpp"
#include "io/run_folder.hpp"
#include "io/run_log.hpp"
#include "parallel/communicator.hpp"
#include "parallel/mpi_session.hpp"
#include "run/diagnostics_output.hpp"
#include "run/field_output.hpp"
#include "run/kokkos_session.hpp"
#include "run/run_checkpoints.hpp"
#include "run/run_clock.hpp"
#include "run/run_report.hpp"
#include "run/simulation.hpp"
#include "run/time_loop.hpp"
#include "util/errors.hpp"

namespace rouleau {

namespace {

using Clock = RunClock::Clock;

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

// What every file of the run carries besides the build's provenance: the case, the run id,
// how it runs, and the hashes of its meshes (`fluid_mesh`: the fluid's output mesh).
std::vector<std::pair<std::string, std::string>> run_provenance_entries(const CaseConfig& config,
                                                                        const std::string& run_id,
                                                                        const Communicator& ranks,
                                                                        const MeshDescription& fluid_mesh,
                                                                        const CaseCells& cells) {
  std::vector<std::pair<std::string, std::string>> entries{
      {"case", config.name},
      {"run_id", run_id},
      {"execution_space", Kokkos::DefaultExecutionSpace::name()},
      {"threads", std::to_string(Kokkos::DefaultHostExecutionSpace().concurrency())},
      {"ranks", std::to_string(ranks.size())},
      {"fluid_mesh_hash", hash_mesh(fluid_mesh.coordinates.data(), fluid_mesh.coordinates.size(),
                                    fluid_mesh.connectivity.data(), fluid_mesh.connectivity.size())}};
  for (const auto& [kind, cell_mesh] : cells.meshes) entries.emplace_back("cell_mesh_hash_" + kind, cell_mesh.hash);
  return entries;
}

// The run itself, once its folder is ready: builds the simulation and its outputs, runs the
// time loop, and reports (`log` is the first rank's, null on the others).
int run_in_folder(const CaseConfig& config, const RunOptions& options, const DerivedQuantities& derived,
                  const Communicator& ranks, const std::string& run_id, RunLog* log, Clock::time_point run_start) {
  const bool writes_files = ranks.rank() == 0;
  const std::string out = options.output_dir;
  const FoundCheckpoint* restart = options.restart.get();
  report_run_opening(config, out);
  Simulation simulation(config, default_mesh_cache_dir(), &ranks);
  const MemoryEstimate memory = estimate_memory(config, Kokkos::DefaultHostExecutionSpace().concurrency());
  report_run_setup(simulation, derived, ranks, memory);

  std::vector<MeshDescription> meshes = output_meshes(simulation);
  const auto provenance_entries = run_provenance_entries(config, run_id, ranks, meshes.front(), simulation.cells());
  const Provenance provenance = build_provenance(provenance_entries);
  const std::map<std::string, std::string> mesh_hashes = mesh_hash_labels(provenance_entries);
  // The volume drift is measured from the cells as placed: before a restart moves them.
  CellDiagnostics cell_diagnostics(simulation.cells(), config, &ranks);
  if (restart) restart_simulation(simulation, *restart, mesh_hashes, out, writes_files);
  const auto earlier_rows = earlier_diagnostics_rows(out, restart, writes_files);
  FieldOutput fields(simulation, ranks, std::move(meshes), provenance, out, restart, writes_files);
  DiagnosticsOutput diagnostics(simulation, std::move(cell_diagnostics), out, earlier_rows, writes_files);
  const RunClock clock(run_start, restart ? restart->data.wall_seconds : 0.0);
  RunCheckpoints checkpoints(config, derived, out, restart, provenance, mesh_hashes, run_id, writes_files);

  TimeLoop loop(simulation, options, ranks, log, clock, {diagnostics, fields, checkpoints});
  const int status = loop.run(restart != nullptr);
  if (status != static_cast<int>(ExitCode::done)) return status;
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
