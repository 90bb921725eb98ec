#include "run/run_case.hpp"

#include <Kokkos_Core.hpp>
#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
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
#include "run/scene.hpp"
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

// Wall time spent per stage, printed at the end of the run.
class StageTimes {
 public:
  template <class F>
  auto time(const std::string& stage, F&& f) {
    const auto start = Clock::now();
    auto result = f();
    seconds_[stage] += std::chrono::duration<double>(Clock::now() - start).count();
    return result;
  }
  void print(std::ostream& out) const {
    out << "time per stage:\n";
    for (const auto& [stage, s] : seconds_) {
      char line[160];
      std::snprintf(line, sizeof line, "  %-28s %10.3f s\n", stage.c_str(), s);
      out << line;
    }
  }

 private:
  std::map<std::string, double> seconds_;
};

std::array<bool, 3> periodic_directions(const DomainConfig& domain) {
  std::array<bool, 3> periodic{};
  for (int d = 0; d < 3; ++d) periodic[d] = domain.boundary[2 * d].type == BoundaryType::periodic;
  return periodic;
}

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

// Diagnostics of the fluid: wall tractions on y walls (shear scenes), mean velocity, and
// for simple shear the relative apparent viscosity τ_w / (μ γ̇).
struct FluidDiagnostics {
  std::vector<std::string> columns() const {
    return {"step", "time_s", "newton_iterations", "gmres_iterations", "momentum_residual", "continuity_residual",
            "mean_velocity_x_um_s", "mean_velocity_y_um_s", "mean_velocity_z_um_s", "wall_shear_stress_y_min_Pa",
            "wall_shear_stress_y_max_Pa", "relative_apparent_viscosity", "wall_time_s"};
  }
  std::vector<double> row(const CaseConfig& config, const FluidSolver& solver, int step,
                          const FluidSolveReport& report, double wall_time) const {
    const auto u = solver.mean_velocity();
    const DomainConfig& domain = config.domain;
    const double area = (domain.upper[0] - domain.lower[0]) * (domain.upper[2] - domain.lower[2]);
    double shear[2] = {NAN, NAN};
    std::vector<std::string> walls;
    for (int k = 0; k < 2; ++k)
      if (domain.boundary[Side::y_min + k].type == BoundaryType::wall) walls.push_back(side_names[Side::y_min + k]);
    const auto forces = solver.boundary_forces(walls);
    for (size_t w = 0; w < walls.size(); ++w) {
      const int k = walls[w] == side_names[Side::y_min] ? 0 : 1;
      // τ_w = μ ∂u_x/∂y at the wall = −n_y F_x / A, with F the force the fluid exerts on the
      // wall and n_y the fluid's outward normal: positive on both walls in simple shear.
      const double outward_normal_y = k == 0 ? -1.0 : 1.0;
      shear[k] = -outward_normal_y * forces[w][0] / area;
    }
    // Simple shear between the y walls: γ̇ = (U_top − U_bottom)/H, τ_w = μ γ̇ for plasma alone.
    double relative_viscosity = NAN;
    const double height = domain.upper[1] - domain.lower[1];
    const double shear_rate =
        (domain.boundary[Side::y_max].velocity[0] - domain.boundary[Side::y_min].velocity[0]) / height;
    if (std::isfinite(shear[1]) && shear_rate != 0.0)
      relative_viscosity = shear[1] / (config.fluid.viscosity * shear_rate);
    return {double(step), solver.time(), double(report.newton_iterations), double(report.gmres_iterations),
            report.momentum_residual, report.continuity_residual, u[0], u[1], u[2], shear[0], shear[1],
            relative_viscosity, wall_time};
  }
};

// Diagnostics of the cells: elastic and interaction energies, neighbour-list rebuilds, and
// the largest change of a cell's enclosed volume since the start (relative).
struct CellDiagnostics {
  std::vector<double> initial_volumes;

  explicit CellDiagnostics(const CaseCells& cells) {
    if (cells.population)
      for (const CellMeasures& m : cells.population->measures()) initial_volumes.push_back(m.volume);
  }
  static std::vector<std::string> columns() {
    return {"elastic_energy_pN_um", "interaction_energy_pN_um", "neighbor_list_rebuilds",
            "largest_relative_volume_change"};
  }
  std::vector<double> row(const CaseCells& cells) const {
    const double elastic = cells.population->compute_internal_forces_and_energy();
    const double interaction = cells.interaction ? cells.interaction->compute_forces_and_energy() : 0.0;
    const double rebuilds = cells.interaction ? cells.interaction->rebuild_count() : 0.0;
    double largest_change = 0.0;
    const std::vector<CellMeasures> now = cells.population->measures();
    for (std::size_t c = 0; c < now.size(); ++c)
      largest_change = std::max(largest_change, std::fabs(now[c].volume / initial_volumes[c] - 1.0));
    return {elastic, interaction, rebuilds, largest_change};
  }
};

}  // namespace

int run_case(const CaseConfig& config, const RunOptions& options) {
  const auto run_start = Clock::now();
  const DerivedQuantities derived = derive_quantities(config);
  const std::vector<Stage> stages = plan_stages(config, derived);
  if (options.explain) {
    std::cout << describe_stages(config, derived, stages);
    return static_cast<int>(ExitCode::done);
  }
  StageTimes times;
  namespace fs = std::filesystem;
  fs::create_directories(options.output_dir);
  const std::string out = options.output_dir;
  write_file_atomically(out + "/case.resolved.toml", resolved_case_toml(config, derived));

  FluidScales scales;
  scales.length = derived.length_scale;
  scales.velocity = derived.velocity_scale;
  scales.pressure = derived.pressure_scale;
  scales.reynolds = derived.reynolds;
  const DomainConfig& domain = config.domain;
  const FluidMesh mesh = times.time("mesh", [&] {
    return make_box_mesh(domain.lower, domain.upper, domain.elements, domain.wall_grading,
                         periodic_directions(domain));
  });
  auto solver = times.time("fluid setup", [&] {
    return std::make_unique<FluidSolver>(mesh, config.fluid, domain.boundary, config.solver, scales, derived.stokes);
  });

  const CaseCells cells =
      times.time("cell meshes", [&] { return make_case_cells(config, default_mesh_cache_dir()); });

  std::vector<MeshDescription> output_meshes{describe_fluid_mesh(mesh)};
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
  FluidDiagnostics diagnostics;
  const CellDiagnostics cell_diagnostics(cells);
  std::vector<std::string> columns = diagnostics.columns();
  if (cells.population) {
    const auto cell_columns = CellDiagnostics::columns();
    columns.insert(columns.end(), cell_columns.begin(), cell_columns.end());
  }
  DiagnosticsTable table(out + "/diagnostics.csv", columns);
  auto add_diagnostics_row = [&](int step, const FluidSolveReport& report) {
    std::vector<double> row = diagnostics.row(config, *solver, step, report,
                                              std::chrono::duration<double>(Clock::now() - run_start).count());
    if (cells.population) {
      const std::vector<double> cell_row = times.time("cell diagnostics", [&] { return cell_diagnostics.row(cells); });
      row.insert(row.end(), cell_row.begin(), cell_row.end());
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
  auto write_fields = [&](int step) {
    if (!fields) return;
    times.time("output", [&] {
      solver->velocity_and_pressure(velocity, pressure);
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
      fields->write_step(step, solver->time(), nodal, {}, moved);
      return 0;
    });
  };
  auto fail = [&](int step, const FluidSolveReport& report) {
    std::ostringstream msg;
    msg << "diverged at step " << step << " (t = " << solver->time() << " s), stage fluid: " << report.failure
        << "; residual momentum " << report.momentum_residual << ", continuity " << report.continuity_residual
        << " (scaled); fields up to the last good step are in " << out << " (checkpoints: not yet implemented)";
    table.flush();
    throw DivergenceError(msg.str());
  };

  write_fields(0);
  if (config.time.mode == TimeMode::steady) {
    const FluidSolveReport report = times.time("fluid solve", [&] { return solver->solve_steady(); });
    if (!report.converged) fail(1, report);
    add_diagnostics_row(1, report);
    write_fields(1);
    std::cerr << "steady solve: " << report.newton_iterations << " Newton, " << report.gmres_iterations
              << " GMRES iterations; residual momentum " << report.momentum_residual << ", continuity "
              << report.continuity_residual << "\n";
  } else {
    const int steps = static_cast<int>(std::llround(config.time.end / config.time.dt));
    ProgressReporter progress(steps, config.time.end, stderr_is_terminal(), std::cerr);
    for (int step = 1; step <= steps; ++step) {
      const FluidSolveReport report =
          times.time("fluid solve", [&] { return solver->advance(config.time.dt, config.time.scheme); });
      if (!report.converged) fail(step, report);
      if (step % config.output.diagnostics_every_steps == 0 || step == steps)
        add_diagnostics_row(step, report);
      if (step % config.output.fields_every_steps == 0 || step == steps) write_fields(step);
      if (options.progress) progress.update(step, solver->time(), report.newton_iterations, report.gmres_iterations);
    }
    if (options.progress) progress.finish();
  }
  table.flush();
  times.print(std::cerr);
  std::cerr << "wrote " << out << "/" << (fields ? "fields.xdmf, " : "") << "diagnostics.csv, case.resolved.toml\n";
  return static_cast<int>(ExitCode::done);
}

CaseDriverRun run_case_driver(int argc, char** argv, const std::string& default_case,
                              const std::string& default_output_dir) {
  CaseDriverRun run;
  run.config = load_case(argc > 1 ? argv[1] : default_case);
  run.options.output_dir = argc > 2 ? argv[2] : default_output_dir;
  run.status = run_case(run.config, run.options);
  return run;
}

}  // namespace rouleau
