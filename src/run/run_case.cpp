#include "run/run_case.hpp"

#include <Kokkos_Core.hpp>
#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "cells/cells_from_case.hpp"
#include "cli/progress.hpp"
#include "config/derived.hpp"
#include "config/load_case.hpp"
#include "config/resolved_case.hpp"
#include "fluid/fluid_solver.hpp"
#include "geometry/cell_mesh.hpp"
#include "io/atomic_file.hpp"
#include "io/diagnostics_table.hpp"
#include "io/provenance.hpp"
#include "io/xdmf_writer.hpp"
#include "rouleau_version.hpp"
#include "coupling/immersed_coupling.hpp"
#include "run/run_diagnostics.hpp"
#include "run/scene.hpp"
#include "run/simulation.hpp"
#include "run/stage_times.hpp"
#include "util/errors.hpp"

namespace rouleau {

std::vector<std::pair<std::string, std::string>> kokkos_runtime_info() {
  std::vector<std::pair<std::string, std::string>> info;
  info.emplace_back("kokkos", ROULEAU_KOKKOS_VERSION);
  info.emplace_back("kokkos-kernels", ROULEAU_KOKKOSKERNELS_VERSION);
  std::string backends;
#ifdef KOKKOS_ENABLE_SERIAL
  backends += "Serial ";
#endif
#ifdef KOKKOS_ENABLE_OPENMP
  backends += "OpenMP ";
#endif
#ifdef KOKKOS_ENABLE_THREADS
  backends += "Threads ";
#endif
#ifdef KOKKOS_ENABLE_CUDA
  backends += "Cuda ";
#endif
#ifdef KOKKOS_ENABLE_HIP
  backends += "HIP ";
#endif
  if (!backends.empty()) backends.pop_back();
  info.emplace_back("kokkos backends", backends);
  info.emplace_back("default execution space", Kokkos::DefaultExecutionSpace::name());
  info.emplace_back("threads", std::to_string(Kokkos::DefaultHostExecutionSpace().concurrency()));
  return info;
}

namespace {

using Clock = std::chrono::steady_clock;

// The fluid mesh as the XDMF writer wants it (host arrays).
MeshDescription describe_fluid_mesh(const FluidMesh& mesh) {
  MeshDescription d;
  d.name = "fluid";
  d.cell_type = mesh.element_type == FluidElementType::hexahedron8 ? CellType::hexahedron8 : CellType::tetrahedron4;
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto c = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_nodes);
  d.coordinates.resize(3 * mesh.num_nodes);
  for (int n = 0; n < mesh.num_nodes; ++n)
    for (int k = 0; k < 3; ++k) d.coordinates[3 * n + k] = x(n, k);
  d.connectivity.resize(static_cast<size_t>(mesh.num_elements) * mesh.nodes_per_element);
  for (int e = 0; e < mesh.num_elements; ++e)
    for (int a = 0; a < mesh.nodes_per_element; ++a) d.connectivity[e * mesh.nodes_per_element + a] = c(e, a);
  return d;
}

}  // namespace

int run_case(const CaseConfig& config, const RunOptions& options) {
  const auto run_start = Clock::now();
  const DerivedQuantities derived = derive_quantities(config);
  const std::vector<Stage> stages = plan_stages(config, derived);
  if (options.explain) {
    std::cout << describe_stages(config, derived, stages);
    return static_cast<int>(ExitCode::done);
  }
  namespace fs = std::filesystem;
  fs::create_directories(options.output_dir);
  const std::string out = options.output_dir;
  write_file_atomically(out + "/case.resolved.toml", resolved_case_toml(config, derived));

  Simulation simulation(config, default_mesh_cache_dir());
  StageTimes& times = simulation.times();
  const FluidSolver& solver = simulation.fluid();
  const CaseCells& cells = simulation.cells();
  ImmersedCoupling* coupling = simulation.coupling();
  std::cerr << "fluid mesh: " << simulation.mesh().num_nodes << " nodes, " << simulation.mesh().num_elements << " "
            << (simulation.mesh().element_type == FluidElementType::tetrahedron4 ? "tetrahedra" : "hexahedra") << ", "
            << solver.fluid_operator().num_unknowns() << " unknowns\n";
  if (coupling && coupling->semi_implicit())
    std::cerr << "semi-implicit coupling: dt = " << config.time.dt << " s (the explicit stable step estimate, "
              << derived.stable_dt << " s, does not bind it)\n";
  else if (coupling)
    std::cerr << "explicit coupling: dt = " << config.time.dt << " s, stable step estimate " << derived.stable_dt
              << " s (" << derived.stable_dt_reason << ")"
              << (config.time.dt > derived.stable_dt ? "; ABOVE IT (coupling.allow_unstable_step = true)" : "")
              << "\n";

  std::vector<MeshDescription> output_meshes{describe_fluid_mesh(simulation.mesh())};
  const MeshDescription& fluid_mesh = output_meshes.front();
  std::vector<std::pair<std::string, std::string>> provenance_entries{
      {"case", config.name},
      {"execution_space", Kokkos::DefaultExecutionSpace::name()},
      {"threads", std::to_string(Kokkos::DefaultHostExecutionSpace().concurrency())},
      {"fluid_mesh_hash", hash_mesh(fluid_mesh.coordinates.data(), fluid_mesh.coordinates.size(),
                                    fluid_mesh.connectivity.data(), fluid_mesh.connectivity.size())}};
  for (const auto& [kind, cell_mesh] : cells.meshes) provenance_entries.emplace_back("cell_mesh_hash_" + kind, cell_mesh.hash);
  if (cells.population) output_meshes.push_back(cells.population->mesh_description());
  const Provenance provenance = build_provenance(provenance_entries);
  std::unique_ptr<XdmfTimeSeries> fields;
  if (config.output.write_fields) fields = std::make_unique<XdmfTimeSeries>(out, "fields", output_meshes, provenance);

  const CellDiagnostics cell_diagnostics(cells, config);
  CouplingDiagnostics coupling_diagnostics;
  const FluidDiagnostics fluid_diagnostics(config, simulation.mesh());
  std::vector<std::string> columns = fluid_diagnostics.columns();
  if (cells.population) {
    const auto cell_columns = cell_diagnostics.columns();
    columns.insert(columns.end(), cell_columns.begin(), cell_columns.end());
  }
  if (coupling) {
    const auto coupling_columns = coupling_diagnostics.columns();
    columns.insert(columns.end(), coupling_columns.begin(), coupling_columns.end());
  }
  DiagnosticsTable table(out + "/diagnostics.csv", columns);
  auto add_diagnostics_row = [&] {
    std::vector<double> row =
        fluid_diagnostics.row(solver, simulation.steps(), simulation.last_report().fluid,
                              std::chrono::duration<double>(Clock::now() - run_start).count());
    if (cells.population) {
      const std::vector<double> cell_row = times.time("cell diagnostics", [&] { return cell_diagnostics.row(cells); });
      row.insert(row.end(), cell_row.begin(), cell_row.end());
    }
    if (coupling) {
      const std::vector<double> coupling_row = coupling_diagnostics.row(simulation.last_report(), times);
      row.insert(row.end(), coupling_row.begin(), coupling_row.end());
    }
    table.add_row(row);
  };

  std::vector<double> velocity, pressure;
  CellPopulation::HostFields cell_fields;
  // The interaction forces per cell node (device, and a node-major host copy for output).
  CellPopulation::NodeVectors node_interaction_forces;
  Kokkos::View<double* [3], Kokkos::LayoutRight, Kokkos::HostSpace> host_interaction_forces;
  if (cells.interaction) {
    node_interaction_forces = CellPopulation::NodeVectors("rouleau::run::interaction_forces", cells.population->num_nodes());
    host_interaction_forces = decltype(host_interaction_forces)("rouleau::run::interaction_forces_host",
                                                                cells.population->num_nodes());
  }
  auto write_fields = [&] {
    if (!fields) return;
    times.time("output", [&] {
      solver.velocity_and_pressure(velocity, pressure);
      std::vector<std::vector<FieldView>> nodal{
          {FieldView{"velocity_um_s", 3, velocity.data()}, FieldView{"pressure_Pa", 1, pressure.data()}}};
      std::vector<const double*> moved{nullptr};
      if (cells.population) {
        cells.population->compute_internal_forces();
        cells.population->copy_fields_to_host(cell_fields);
        nodal.push_back({FieldView{"displacement_um", 3, cell_fields.displacement.data()},
                         FieldView{"velocity_um_s", 3, cell_fields.velocity.data()},
                         FieldView{"internal_force_pN", 3, cell_fields.internal_force.data()},
                         FieldView{"cell_id", 1, cell_fields.cell_id.data()}});
        if (cells.interaction) {
          cells.interaction->compute_forces();
          cells.interaction->copy_forces_to_nodes(node_interaction_forces);
          Kokkos::deep_copy(host_interaction_forces, node_interaction_forces);
          nodal.back().push_back(FieldView{"interaction_force_pN", 3, host_interaction_forces.data()});
        }
        moved.push_back(cell_fields.positions.data());
      }
      fields->write_step(simulation.steps(), simulation.time(), nodal, {}, moved);
    });
  };

  write_fields();
  try {
    if (config.time.mode == TimeMode::steady) {
      const FluidSolveReport& report = simulation.solve_steady().fluid;
      add_diagnostics_row();
      write_fields();
      std::cerr << "steady solve: " << report.newton_iterations << " Newton, " << report.gmres_iterations
                << " GMRES iterations; residual momentum " << report.momentum_residual << ", continuity "
                << report.continuity_residual << "\n";
    } else {
      const int steps = static_cast<int>(std::llround(config.time.end / config.time.dt));
      ProgressReporter progress(steps, config.time.end, stderr_is_terminal(), std::cerr);
      for (int step = 1; step <= steps; ++step) {
        const FluidSolveReport& report = simulation.advance().fluid;
        if (step % config.output.diagnostics_every_steps == 0 || step == steps) add_diagnostics_row();
        if (step % config.output.fields_every_steps == 0 || step == steps) write_fields();
        if (options.progress)
          progress.update(step, simulation.time(), report.newton_iterations, report.gmres_iterations);
      }
      if (options.progress) progress.finish();
    }
  } catch (const DivergenceError& error) {
    table.flush();
    throw DivergenceError(std::string(error.what()) + "; fields up to the last good step are in " + out +
                          " (checkpoints: not yet implemented)");
  }
  table.flush();
  times.print(std::cerr);
  std::cerr << "wrote " << out << "/" << (fields ? "fields.xdmf, " : "") << "diagnostics.csv, case.resolved.toml\n"
            << (fields ? "ParaView: open " + out + "/fields.xdmf; " : std::string()) << "figures: scripts/plot_diagnostics.py "
            << out << "\n";
  return static_cast<int>(ExitCode::done);
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
  run.status = run_reporting_errors(
      [&] {
        run.config = load_case(command_line.case_path, command_line.overrides);
        return run_case(run.config, run.options);
      },
      std::cerr);
  run.ran = run.status == 0 && !run.options.explain;
  return run;
}

}  // namespace rouleau
