#include "coupling/immersed_coupling.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "config/cell_kinds.hpp"
#include "kernels/cell_motion.hpp"
#include "kernels/fsi_force.hpp"
#include "kernels/state_checks.hpp"
#include "run/profiling_region.hpp"
#include "util/view_transfer.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;

// m_I = (ρ_s − ρ_f) V_I, V_I = Σ_{e ∋ I} V0_e / 4, ρ_s the density of the node's cell's kind.
std::vector<double> nodal_excess_mass(const CellPopulation& population, const CaseConfig& config) {
  auto element_nodes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.element_nodes());
  auto element_cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.element_cell());
  auto volume = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.reference_volume());
  std::vector<double> mass(population.num_nodes(), 0.0);
  for (int e = 0; e < population.num_elements(); ++e) {
    const CellKindConfig& kind = *find_cell_kind(config, config.cells[element_cell(e)].kind);
    const double excess_density = kind.density - config.fluid.density;
    for (int a = 0; a < 4; ++a) mass[element_nodes(e, a)] += 0.25 * excess_density * volume(e);
  }
  return mass;
}

// transferred(n) = 1 for the nodes whose fluid transfer (RKPM rows) this rank needs: those
// of its own cells (computed(n)) and of the cells its Morse pairs reach (in_list of the
// node's cell; none when `in_list` is empty).
void mark_transferred_nodes(const Kokkos::View<const int*>& node_cell, const Kokkos::View<const int*>& computed,
                            const Kokkos::View<const int*>& in_list, const Kokkos::View<int*>& transferred) {
  const bool with_list = in_list.extent(0) > 0;
  Kokkos::parallel_for(
      "rouleau::ImmersedCoupling::transferred_nodes", Kokkos::RangePolicy<ExecSpace>(0, transferred.extent(0)),
      KOKKOS_LAMBDA(const int n) { transferred(n) = computed(n) || (with_list && in_list(node_cell(n))); });
}

// Σ_i a_i b_i over a flat or a (node, 3) View pair.
template <class View, class OtherView>
double dot(const View& a, const OtherView& b) {
  double sum = 0.0;
  if constexpr (View::rank == 1) {
    Kokkos::parallel_reduce(
        "rouleau::ImmersedCoupling::dot", Kokkos::RangePolicy<ExecSpace>(0, a.extent(0)),
        KOKKOS_LAMBDA(const int i, double& s) { s += a(i) * b(i); }, sum);
  } else {
    Kokkos::parallel_reduce(
        "rouleau::ImmersedCoupling::dot", Kokkos::RangePolicy<ExecSpace>(0, a.extent(0)),
        KOKKOS_LAMBDA(const int i, double& s) { s += a(i, 0) * b(i, 0) + a(i, 1) * b(i, 1) + a(i, 2) * b(i, 2); },
        sum);
  }
  return sum;
}

// "(x, y, z)" of node `node` of a (node, 3) View (for an error message: copies the View
// to the host).
std::string node_vector_text(const CellPopulation::NodeVectors& vectors, const int node) {
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), vectors);
  std::ostringstream text;
  text << "(" << host(node, 0) << ", " << host(node, 1) << ", " << host(node, 2) << ")";
  return text.str();
}
}  // namespace

ImmersedCoupling::ImmersedCoupling(FluidSolver& fluid, const CaseCells& cells, const CaseConfig& config)
    : fluid_(fluid),
      population_(*cells.population),
      interaction_(cells.interaction.get()),
      rkpm_(fluid.mesh(), config.coupling.support_elements),
      skip_unneeded_(config.scene.skip_unneeded_stages),
      gravity_(config.coupling.gravity) {
  const int nodes = population_.num_nodes();
  fsi_forces_ = NodeVectors("rouleau::ImmersedCoupling::fsi_forces", nodes);
  interpolated_ = NodeVectors("rouleau::ImmersedCoupling::interpolated", nodes);
  previous_velocities_ = NodeVectors("rouleau::ImmersedCoupling::previous_velocities", nodes);
  fluid_load_ = Kokkos::View<double*>("rouleau::ImmersedCoupling::fluid_load", fluid.num_global_unknowns());
  if (fluid.distribution())
    cell_carrier_ = Kokkos::View<double*>("rouleau::ImmersedCoupling::cell_carrier", fluid.num_global_unknowns());
  fluid_.set_immersed_forces_in_stabilization(config.coupling.forces_in_stabilization);
  if (config.coupling.subscale_velocity) {
    total_velocity_ =
        Kokkos::View<double*>("rouleau::ImmersedCoupling::total_velocity", fluid.fluid_operator().num_unknowns());
    if (fluid.distribution())
      global_state_ = Kokkos::View<double*>("rouleau::ImmersedCoupling::global_state", fluid.num_global_unknowns());
  }
  if (interaction_) interaction_forces_ = NodeVectors("rouleau::ImmersedCoupling::interaction_forces", nodes);
  if (config.vessel.enabled && config.vessel.wall_repulsion_pressure > 0.0) {
    wall_ = std::make_unique<WallRepulsion>(config.vessel.profile, config.vessel.wall_repulsion_pressure,
                                            config.vessel.wall_repulsion_range);
    wall_forces_ = NodeVectors("rouleau::ImmersedCoupling::wall_forces", nodes);
  }
  // The inertia/buoyancy stage changes nothing when every cell is as dense as the fluid.
  const std::vector<double> mass = nodal_excess_mass(population_, config);
  bool any_excess = false;
  for (double m : mass) any_excess = any_excess || m != 0.0;
  runs_inertia_ = any_excess || !skip_unneeded_;
  if (runs_inertia_) {
    excess_mass_ = Kokkos::View<double*>("rouleau::ImmersedCoupling::excess_mass", nodes);
    auto host = Kokkos::create_mirror_view(excess_mass_);
    for (int n = 0; n < nodes; ++n) host(n) = mass[n];
    Kokkos::deep_copy(excess_mass_, host);
  }
  if (config.coupling.scheme == CouplingScheme::semi_implicit) {
    stiffness_scratch_ = NodeVectors("rouleau::ImmersedCoupling::stiffness_scratch", nodes);
    force_change_ = NodeVectors("rouleau::ImmersedCoupling::force_change", nodes);
    stiffness_ = std::make_unique<CellStiffness>(
        rkpm_, population_.positions(),
        [this](const NodeVectors& out) {
          differenced_forces(population_, wall_.get(), stiffness_scratch_, out, computed_nodes_);
        },
        interaction_, fluid.scales());
  }
  // Without skips the RKPM correction runs everywhere (it changes nothing but round-off
  // where the plain window reproduces linear fields).
  rkpm_.always_correct(!skip_unneeded_);
}

ImmersedCoupling::StepReport ImmersedCoupling::advance(double dt, TimeScheme scheme, StageTimes& times) {
  ProfilingRegion region("rouleau::ImmersedCoupling::advance");
  StepReport report;
  // 1. forces on the cells at x^n
  times.time(elastic_stage, [&] { population_.compute_internal_forces(); });
  if (interaction_)
    times.time(interaction_stage, [&] {
      // Without skips the list is rebuilt every step (the skin then changes nothing).
      if (!skip_unneeded_) interaction_->rebuild();
      interaction_->compute_forces();
      interaction_->copy_forces_to_nodes(interaction_forces_);
    });
  if (wall_)
    times.time(wall_stage, [&] {
      wall_->compute_forces(population_.positions(), population_.surface_area_weights(), wall_forces_);
      if (shares_) keep_nodes(wall_forces_, computed_nodes_);
    });
  times.time(runs_inertia_ ? inertia_stage : elastic_stage, [&] {
    FsiForceFunctor<NodeVectors, Kokkos::View<double*>> sum{population_.internal_forces(),
                                                            interaction_forces_,
                                                            wall_forces_,
                                                            excess_mass_,
                                                            population_.velocities(),
                                                            previous_velocities_,
                                                            {gravity_[0], gravity_[1], gravity_[2]},
                                                            previous_dt_ > 0.0 ? 1.0 / previous_dt_ : 0.0,
                                                            fsi_forces_};
    Kokkos::parallel_for("rouleau::ImmersedCoupling::fsi_force",
                         Kokkos::RangePolicy<ExecSpace>(0, population_.num_nodes()), sum);
  });
  // Every force must be finite before it reaches the fluid: name the first node that is not.
  const int non_finite = first_non_finite_row(ExecSpace(), fsi_forces_, "rouleau::ImmersedCoupling::check_forces");
  if (non_finite >= 0) {
    std::ostringstream what;
    what << "cell forces: the force on node " << non_finite << " of cell " << population_.cell_of_node(non_finite)
         << " is NaN or Inf: " << node_vector_text(fsi_forces_, non_finite) << " pN in all, of which elastic "
         << node_vector_text(population_.internal_forces(), non_finite) << " pN; the node is at "
         << node_vector_text(population_.positions(), non_finite) << " um";
    throw std::runtime_error(what.str());
  }
  // 2. spread, with the supports at x^n (also those of the interpolation below); across
  // ranks the cells read the fluid at their supports alone, and a share's forces are
  // summed there over the ranks.
  times.time(spread_stage, [&] {
    if (shares_) restrict_transfers();
    try {
      rkpm_.update(population_.positions());
    } catch (const PointsOutsideFluidError& error) {
      std::ostringstream what;
      what << spread_stage << ": cell " << population_.cell_of_node(error.first_point())
           << " has left the fluid domain: its node " << error.first_point() << " is at "
           << node_vector_text(population_.positions(), error.first_point()) << " um, with no fluid node in its support ("
           << error.count() << " cell nodes outside in all)";
      throw std::runtime_error(what.str());
    }
    // Across ranks the union of the ranks' supports is replicated (each rank's own alone
    // when every rank transfers every cell).
    if (fluid_.distribution())
      fluid_.set_replicated_nodes(shares_ ? fluid_.distribution()->nodes_of_any_rank(rkpm_.support_nodes())
                                          : rkpm_.support_nodes());
    Kokkos::deep_copy(fluid_load_, 0.0);
    rkpm_.spread(fsi_forces_, fluid_load_, fluid_unknowns_per_node);
    if (shares_) fluid_.sum_over_ranks(fluid_load_);
    fluid_.set_immersed_forces(fluid_load_);
  });
  // across ranks each rank counts its own cells' points
  report.corrected_points = shares_ ? static_cast<int>(fluid_.distribution()->communicator().sum(
                                          static_cast<long long>(rkpm_.corrected_points())))
                                    : rkpm_.corrected_points();
  // 3. the fluid
  if (stiffness_) {
    times.time(stiffness_stage, [&] { stiffness_->linearize(dt); });
    // The cells move with u_h + u' when total_velocity_ is there: Ŝ then acts on it.
    fluid_.set_immersed_stiffness(stiffness_.get(), total_velocity_.extent(0) > 0);
  }
  report.fluid = times.time(fluid_stage, [&] { return fluid_.advance(dt, scheme); });
  if (stiffness_) fluid_.set_immersed_stiffness(nullptr);
  if (!report.fluid.converged) return report;
  // The velocity the cells move with: u_h, or u_h + u' (coupling.subscale_velocity), in
  // the global numbering: the fluid's own vectors on one rank, their global copies at the
  // cells' supports across ranks.
  Kokkos::View<const double*> cell_carrier = fluid_.state(), global_state = fluid_.state();
  if (total_velocity_.extent(0) > 0) {
    times.time(interpolate_stage, [&] { fluid_.total_velocity(total_velocity_); });
    cell_carrier = total_velocity_;
  }
  if (fluid_.distribution())
    times.time(interpolate_stage, [&] {
      fluid_.gather_global(cell_carrier, cell_carrier_);
      if (global_state_.extent(0) > 0) fluid_.gather_global(fluid_.state(), global_state_);
      global_state = global_state_.extent(0) > 0 ? global_state_ : cell_carrier_;
      cell_carrier = cell_carrier_;
    });
  // The semi-implicit step's forces f^n + K Δt I u^{n+1}, spread as the fluid felt them.
  if (stiffness_)
    times.time(stiffness_stage, [&] {
      stiffness_->force_change(cell_carrier, force_change_);
      add_node_vectors(fsi_forces_, force_change_);
      Kokkos::deep_copy(fluid_load_, 0.0);
      rkpm_.spread(fsi_forces_, fluid_load_, fluid_unknowns_per_node);
      if (shares_) fluid_.sum_over_ranks(fluid_load_);
      fluid_.set_immersed_forces(fluid_load_);
    });
  // 4. interpolate; across ranks each cell's velocities come from the rank computing it.
  times.time(interpolate_stage, [&] {
    rkpm_.interpolate(cell_carrier, fluid_unknowns_per_node, interpolated_);
    if (shares_) {
      keep_nodes(interpolated_, computed_nodes_);
      sum_over_ranks(interpolated_);
    }
  });
  // 5. move
  double largest_speed2 = 0.0;
  times.time(move_stage, [&] {
    MoveCellsFunctor<NodeVectors> move{interpolated_,           population_.velocities(), previous_velocities_,
                                       population_.positions(), fluid_.scales().velocity, dt};
    Kokkos::parallel_reduce("rouleau::ImmersedCoupling::move",
                            Kokkos::RangePolicy<ExecSpace>(0, population_.num_nodes()), move,
                            Kokkos::Max<double>(largest_speed2));
  });
  previous_dt_ = dt;
  report.finite = largest_speed2 < MoveCellsFunctor<NodeVectors>::non_finite_speed2;
  report.largest_cell_speed = std::sqrt(largest_speed2);
  // The power of the step's forces, on the fluid's side and on the cells' (they agree:
  // interpolation and spreading are transposes of each other).
  report.power_spread = dot(fluid_load_, global_state) * fluid_.scales().velocity;
  report.power_interpolated = dot(fsi_forces_, population_.velocities());
  if (shares_) report.power_interpolated = fluid_.distribution()->communicator().sum(report.power_interpolated);
  return report;
}

void ImmersedCoupling::share_cells(const std::vector<int>& cells) {
  if (!fluid_.distribution())
    throw std::logic_error("rouleau::ImmersedCoupling::share_cells: the fluid is on one rank");
  population_.share_work(cells);
  if (interaction_) interaction_->share_rows(cells);
  std::vector<int> computed(population_.num_nodes(), 0);
  const std::vector<int>& first = population_.cell_first_node();
  const std::vector<int>& count = population_.cell_node_count();
  for (const int c : cells)
    for (int n = first[c]; n < first[c] + count[c]; ++n) computed[n] = 1;
  computed_nodes_ = device_copy(computed, "rouleau::ImmersedCoupling::computed_nodes");
  transferred_nodes_ = Kokkos::View<int*>();  // marked anew at the next spread (restrict_transfers)
  // The inertia and buoyancy forces of this rank's nodes alone.
  if (excess_mass_.extent(0) > 0) {
    if (every_excess_mass_.extent(0) == 0) {
      every_excess_mass_ = Kokkos::View<double*>("rouleau::ImmersedCoupling::every_excess_mass", excess_mass_.extent(0));
      Kokkos::deep_copy(every_excess_mass_, excess_mass_);
    }
    auto mass = excess_mass_;
    auto every_mass = every_excess_mass_;
    auto computed_node = computed_nodes_;
    Kokkos::parallel_for(
        "rouleau::ImmersedCoupling::share_excess_mass", Kokkos::RangePolicy<ExecSpace>(0, mass.extent(0)),
        KOKKOS_LAMBDA(const int n) { mass(n) = computed_node(n) ? every_mass(n) : 0.0; });
  }
  shares_ = true;
  fluid_.set_immersed_shares(true);
}

void ImmersedCoupling::restrict_transfers() {
  const int version = interaction_ ? interaction_->list_version() : 0;
  if (transferred_nodes_.extent(0) > 0 && version == transferred_list_version_) return;
  if (transferred_nodes_.extent(0) == 0)
    transferred_nodes_ = Kokkos::View<int*>("rouleau::ImmersedCoupling::transferred_nodes", population_.num_nodes());
  mark_transferred_nodes(population_.node_cell(), computed_nodes_,
                         interaction_ ? interaction_->cells_in_list() : Kokkos::View<int*>(), transferred_nodes_);
  transferred_list_version_ = version;
  rkpm_.restrict_rows(transferred_nodes_, computed_nodes_);
}

void ImmersedCoupling::sum_over_ranks(const NodeVectors& values) {
  if (host_node_vectors_.extent(0) != values.extent(0))
    host_node_vectors_ = Kokkos::create_mirror(values);  // a buffer of its own, also on the host
  Kokkos::deep_copy(host_node_vectors_, values);
  fluid_.distribution()->communicator().sum(host_node_vectors_.data(), 3 * static_cast<int>(values.extent(0)));
  Kokkos::deep_copy(values, host_node_vectors_);
}

void ImmersedCoupling::save_state(CheckpointData& data) const {
  data.reals["coupling/previous_velocities"] = to_flat_vector(previous_velocities_);
  data.reals["coupling/previous_dt"] = {previous_dt_};
}

void ImmersedCoupling::restore_state(const CheckpointData& data) {
  from_flat_vector(data.real("coupling/previous_velocities", 3LL * population_.num_nodes()), previous_velocities_,
                   "coupling/previous_velocities");
  previous_dt_ = data.real("coupling/previous_dt", 1).front();
}

}  // namespace rouleau
