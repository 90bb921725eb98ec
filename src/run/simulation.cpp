#include "run/simulation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "config/derived.hpp"
#include "kernels/state_checks.hpp"
#include "util/errors.hpp"

namespace rouleau {

FluidMesh make_case_mesh(const CaseConfig& config, const std::string& mesh_cache_dir) {
  if (config.vessel.enabled) {
    try {
      return make_vessel_fluid_mesh(vessel_mesh(config.vessel.profile, config.vessel.sizes, mesh_cache_dir),
                                    config.vessel.profile);
    } catch (const std::runtime_error& error) {
      throw InputError(config.source_file, "vessel", error.what());
    }
  }
  const DomainConfig& domain = config.domain;
  std::array<bool, 3> periodic{};
  for (int d = 0; d < 3; ++d) periodic[d] = domain.boundary[2 * d].type == BoundaryType::periodic;
  return make_box_mesh(domain.lower, domain.upper, domain.elements, domain.wall_grading, periodic);
}

Simulation::Simulation(const CaseConfig& config, const std::string& mesh_cache_dir, const Communicator* ranks)
    : config_(config), derived_(derive_quantities(config)), plan_(plan_scene(config_, derived_)) {
  const bool several_ranks = ranks && ranks->size() > 1;
  // The first rank makes (and caches) the meshes, the others then read them.
  if (several_ranks && ranks->rank() > 0) ranks->barrier();
  FluidScales scales;
  scales.length = derived_.length_scale;
  scales.velocity = derived_.velocity_scale;
  scales.pressure = derived_.pressure_scale;
  scales.reynolds = derived_.reynolds;
  mesh_ = times_.time("mesh", [&] { return make_case_mesh(config_, mesh_cache_dir); });
  // (a case without cells has no such stage: the table lists the stages that ran)
  if (!config_.cells.empty()) cells_ = times_.time("cell meshes", [&] { return make_case_cells(config_, mesh_cache_dir); });
  if (several_ranks && ranks->rank() == 0) ranks->barrier();
  if (several_ranks)
    distribution_ = times_.time("fluid setup", [&] { return std::make_unique<FluidDistribution>(*ranks, mesh_); });
  // The preconditioner "auto" stands for (derived_.preconditioner); across ranks, where the
  // fast diagonalization does not run, the multigrid.
  SolverConfig solver = config_.solver;
  solver.preconditioner = derived_.preconditioner;
  if (several_ranks && config_.solver.preconditioner == PreconditionerType::automatic)
    solver.preconditioner = PreconditionerType::multigrid;
  fluid_ = times_.time("fluid setup", [&] {
    return std::make_unique<FluidSolver>(mesh_, config_.fluid, case_boundaries(config_), solver, scales,
                                         derived_.stokes, distribution_.get());
  });
  // The stencil changes Aδ only by round-off; scene.skip_unneeded_stages = false keeps the
  // element-by-element path for comparisons.
  fluid_->allow_stencil(plan_.stencil);
  if (cells_.population) cell_forces_ = std::make_unique<CellForces>(*cells_.population, cells_.interaction.get(), config_, plan_);
  // The cells move with the fluid in a time loop; a steady solve keeps them in place.
  if (cells_.population && plan_.moves_cells)
    coupling_ = times_.time("coupling setup", [&] {
      return std::make_unique<ImmersedCoupling>(*fluid_, cells_, *cell_forces_, config_, plan_);
    });
  if (coupling_)
    for (const CellMeasures& m : cells_.population->measures()) initial_volumes_.push_back(m.volume);
  if (coupling_ && distribution_) assign_cells_to_ranks();
}

void Simulation::assign_cells_to_ranks() {
  std::vector<std::array<double, 3>> centroids;
  for (const CellMeasures& m : cells_.population->measures()) centroids.push_back(m.centroid);
  std::vector<int> ranks = distribution_->rank_holding(centroids);
  if (ranks == cell_ranks_) return;
  if (!cell_ranks_.empty())
    for (std::size_t c = 0; c < ranks.size(); ++c) cell_rank_changes_ += ranks[c] != cell_ranks_[c];
  cell_ranks_ = std::move(ranks);
  std::vector<int> mine;
  for (std::size_t c = 0; c < cell_ranks_.size(); ++c)
    if (cell_ranks_[c] == distribution_->communicator().rank()) mine.push_back(static_cast<int>(c));
  coupling_->share_cells(mine);
}

void Simulation::diverged(const std::string& stage, const std::string& what) const {
  std::ostringstream msg;
  msg << "diverged at step " << steps_ + 1 << " (t = " << fluid_->time() << " s), stage " << stage << ": " << what;
  throw DivergenceError(msg.str());
}

namespace {
std::string fluid_failure(const FluidSolveReport& report) {
  std::ostringstream msg;
  msg << report.failure << "; residual momentum " << report.momentum_residual << ", continuity "
      << report.continuity_residual << " (scaled)";
  return msg.str();
}
}  // namespace

void Simulation::check_fluid_solve() const {
  // A failed solve names the first NaN or Inf of the state when there is one.
  check_fluid_state();
  if (!last_report_.fluid.converged) diverged("fluid", fluid_failure(last_report_.fluid));
}

void Simulation::check_fluid_state() const {
  const int per_node = fluid_unknowns_per_node;
  const int row = first_non_finite_row(Kokkos::DefaultExecutionSpace(), fluid_->state(), "rouleau::Simulation::check_fluid");
  if (row < 0) return;
  auto value = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(fluid_->state(), row));
  static const char* const unknown_names[] = {"u", "v", "w", "p"};
  std::ostringstream what;
  what << "the fluid state is NaN or Inf: unknown " << unknown_names[row % per_node] << " of node " << row / per_node
       << " is " << value() << " (scaled), the first such";
  if (!last_report_.fluid.converged) what << "; the solver: " << fluid_failure(last_report_.fluid);
  diverged("fluid", what.str());
}

void Simulation::check_cell_elements() const {
  const auto worst = cells_.population->most_compressed_element();
  if (worst.volume_ratio > 0.0) return;
  std::ostringstream what;
  what << "element " << worst.element << " of cell " << worst.cell
       << " is inverted: its volume ratio J = det F is " << worst.volume_ratio << " (<= 0)";
  diverged(ImmersedCoupling::move_stage, what.str());
}

const CellForceState& Simulation::cell_forces(const bool with_energies) {
  if (!cell_forces_) throw std::logic_error("rouleau::Simulation::cell_forces: the case has no cells");
  cell_forces_->ensure(with_energies, times_);
  return cell_forces_->state();
}

void Simulation::set_cell_positions(const Kokkos::View<const double* [3], Kokkos::HostSpace>& positions) {
  if (!cell_forces_) throw std::logic_error("rouleau::Simulation::set_cell_positions: the case has no cells");
  const auto& x = cells_.population->positions();
  if (positions.extent(0) != x.extent(0))
    throw std::invalid_argument("rouleau::Simulation::set_cell_positions: " + std::to_string(positions.extent(0)) +
                                " positions for " + std::to_string(x.extent(0)) + " cell nodes");
  auto mirror = Kokkos::create_mirror_view(x);
  for (std::size_t n = 0; n < x.extent(0); ++n)
    for (int d = 0; d < 3; ++d) mirror(n, d) = positions(n, d);
  cells_.population->set_positions(mirror);
  cell_forces_->mark_stale();
}

const ImmersedCoupling::StepReport& Simulation::advance(const bool with_energies) {
  const TimeConfig& time = config_.time;
  // Across ranks a cell's forces are computed by the rank holding its centroid.
  if (coupling_ && distribution_) times_.time("cell ranks", [&] { assign_cells_to_ranks(); });
  if (coupling_) {
    try {
      last_report_ = coupling_->advance(time.dt, time.scheme, with_energies, times_);
    } catch (const std::runtime_error& error) {
      diverged("coupling", error.what());
    }
  } else {
    last_report_ = ImmersedCoupling::StepReport{};
    last_report_.fluid = times_.time(ImmersedCoupling::fluid_stage, [&] { return fluid_->advance(time.dt, time.scheme); });
  }
  check_fluid_solve();
  if (!last_report_.finite) diverged(ImmersedCoupling::move_stage, "a cell node's interpolated velocity is NaN or Inf");
  if (coupling_) {
    check_cell_elements();
    // |V_c / V_c0 − 1| ≤ tolerance for every cell (NaN fails too).
    const std::vector<CellMeasures> now = cells_.population->measures();
    for (std::size_t c = 0; c < now.size(); ++c) {
      const double change = now[c].volume / initial_volumes_[c] - 1.0;
      if (!(std::fabs(change) <= config_.coupling.volume_tolerance)) {
        std::ostringstream what;
        what << "cell " << c << "'s enclosed volume is " << now[c].volume << " um^3, " << 100.0 * change
             << " % from its initial " << initial_volumes_[c] << " um^3 (coupling.volume_tolerance = "
             << config_.coupling.volume_tolerance << ")";
        diverged(ImmersedCoupling::move_stage, what.str());
      }
    }
  }
  ++steps_;
  return last_report_;
}

void Simulation::save_state(CheckpointData& data) const {
  data.step = steps_;
  data.time = fluid_->time();
  fluid_->save_state(data);
  if (cells_.population) cells_.population->save_state(data);
  if (cells_.interaction) cells_.interaction->save_state(data);
  if (coupling_) coupling_->save_state(data);
  std::vector<double> seconds;
  std::string stages;
  for (const auto& [stage, s] : times_.seconds_by_stage()) {
    stages += stage + "\n";
    seconds.push_back(s);
  }
  data.labels["stage_names"] = stages;
  data.reals["run/stage_seconds"] = seconds;
}

void Simulation::restore_state(const CheckpointData& data) {
  fluid_->restore_state(data);
  if (cells_.population) cells_.population->restore_state(data);
  if (cells_.interaction) cells_.interaction->restore_state(data);
  if (coupling_) coupling_->restore_state(data);
  if (cell_forces_) cell_forces_->mark_stale();  // the forces at the restored positions
  steps_ = static_cast<int>(data.step);
  const std::vector<double>& seconds = data.real("run/stage_seconds");
  std::istringstream stages(data.label("stage_names"));
  std::string stage;
  for (std::size_t i = 0; std::getline(stages, stage) && i < seconds.size(); ++i) times_.add(stage, seconds[i]);
}

const ImmersedCoupling::StepReport& Simulation::solve_steady() {
  last_report_ = ImmersedCoupling::StepReport{};
  last_report_.fluid = times_.time(ImmersedCoupling::fluid_stage, [&] { return fluid_->solve_steady(); });
  check_fluid_solve();
  ++steps_;
  return last_report_;
}

}  // namespace rouleau
