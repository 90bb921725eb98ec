#include "coupling/immersed_coupling.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "config/cell_kinds.hpp"
#include "kernels/cell_motion.hpp"
#include "kernels/fsi_force.hpp"
#include "kernels/state_checks.hpp"
#include "util/profiling_region.hpp"
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
std::string node_vector_text(const CellPopulation::ConstNodeVectors& vectors, const int node) {
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), vectors);
  std::ostringstream text;
  text << "(" << host(node, 0) << ", " << host(node, 1) << ", " << host(node, 2) << ")";
  return text.str();
}

// Throws std::runtime_error naming the first node whose force is NaN or Inf, with its
// elastic part and position.
void check_finite_forces(const CellPopulation::NodeVectors& forces, const CellPopulation::ConstNodeVectors& elastic,
                         const CellPopulation& population) {
  const int node = first_non_finite_row(ExecSpace(), forces, "rouleau::ImmersedCoupling::check_forces");
  if (node < 0) return;
  std::ostringstream what;
  what << "cell forces: the force on node " << node << " of cell " << population.cell_of_node(node)
       << " is NaN or Inf: " << node_vector_text(forces, node) << " pN in all, of which elastic "
       << node_vector_text(elastic, node) << " pN; the node is at " << node_vector_text(population.positions(), node)
       << " um";
  throw std::runtime_error(what.str());
}

// The RKPM supports and weights at the cells' current positions; throws
// std::runtime_error naming a cell node that has left the fluid domain.
void update_rkpm_supports(RkpmCoupler& rkpm, const CellPopulation& population) {
  try {
    rkpm.update(population.positions());
  } catch (const PointsOutsideFluidError& error) {
    std::ostringstream what;
    what << ImmersedCoupling::spread_stage << ": cell " << population.cell_of_node(error.first_point())
         << " has left the fluid domain: its node " << error.first_point() << " is at "
         << node_vector_text(population.positions(), error.first_point()) << " um, with no fluid node in its support ("
         << error.count() << " cell nodes outside in all)";
    throw std::runtime_error(what.str());
  }
}
}  // namespace

ImmersedCoupling::ImmersedCoupling(FluidSolver& fluid, const CaseCells& cells, CellForces& forces,
                                   const CaseConfig& config, const ScenePlan& plan)
    : fluid_(fluid),
      population_(*cells.population),
      interaction_(plan.morse_forces ? cells.interaction.get() : nullptr),
      forces_(forces),
      rkpm_(fluid.mesh(), config.coupling.support_elements),
      gravity_(config.coupling.gravity) {
  const int nodes = population_.num_nodes();
  const bool spans_ranks = fluid.exchange().spans_ranks();
  state_.fsi_forces = NodeVectors("rouleau::ImmersedCoupling::fsi_forces", nodes);
  state_.interpolated = NodeVectors("rouleau::ImmersedCoupling::interpolated", nodes);
  state_.previous_velocities = NodeVectors("rouleau::ImmersedCoupling::previous_velocities", nodes);
  state_.cell_velocities = state_.interpolated;
  if (plan.film_drainage) {
    if (spans_ranks)
      throw std::invalid_argument(
          "rouleau::ImmersedCoupling: coupling.film_open_gap_um: the film model runs on one MPI rank");
    films_ = std::make_unique<FilmDrainage>(population_, config.coupling.film_open_gap, config.fluid.viscosity,
                                            config.coupling.film_model);
    state_.cell_velocities = NodeVectors("rouleau::ImmersedCoupling::cell_velocities", nodes);
  }
  fluid_load_ = Kokkos::View<double*>("rouleau::ImmersedCoupling::fluid_load", fluid.num_global_unknowns());
  state_.fluid_terms.loads = fluid_load_;
  state_.fluid_terms.loads_in_stabilization = config.coupling.forces_in_stabilization;
  state_.felt_forces = state_.fsi_forces;
  state_.felt_terms = state_.fluid_terms;
  if (spans_ranks)
    cell_carrier_ = Kokkos::View<double*>("rouleau::ImmersedCoupling::cell_carrier", fluid.num_global_unknowns());
  if (config.coupling.subscale_velocity) {
    total_velocity_ =
        Kokkos::View<double*>("rouleau::ImmersedCoupling::total_velocity", fluid.fluid_operator().num_unknowns());
    if (spans_ranks)
      global_state_ = Kokkos::View<double*>("rouleau::ImmersedCoupling::global_state", fluid.num_global_unknowns());
  }
  if (plan.inertia) {
    const std::vector<double> mass = nodal_excess_mass(population_, config);
    excess_mass_ = device_copy(mass, "rouleau::ImmersedCoupling::excess_mass");
  }
  if (plan.semi_implicit) {
    stiffness_scratch_ = NodeVectors("rouleau::ImmersedCoupling::stiffness_scratch", nodes);
    force_change_ = NodeVectors("rouleau::ImmersedCoupling::force_change", nodes);
    state_.felt_forces = NodeVectors("rouleau::ImmersedCoupling::felt_forces", nodes);
    felt_load_ = Kokkos::View<double*>("rouleau::ImmersedCoupling::felt_load", fluid.num_global_unknowns());
    state_.felt_terms.loads = felt_load_;
    // The elastic and wall forces at trial positions, differenced (the Morse part is exact).
    stiffness_ = std::make_unique<CellStiffness>(
        nodes, rkpm_,
        [this](const NodeVectors& positions, const NodeVectors& out) {
          differenced_forces(population_, forces_.wall(), positions, stiffness_scratch_, out, forces_.computed_nodes());
        },
        interaction_, fluid.scales());
  }
  // Without skips the RKPM correction runs everywhere (it changes nothing but round-off
  // where the plain window reproduces linear fields).
  rkpm_.always_correct(plan.rkpm_correction_everywhere);

  // 1. Reads the force stages' forces at x^n (CellForces), v^n, v^{n−1} and Δt^{n−1};
  //    writes state_.fsi_forces. Every force must be finite before it reaches the fluid.
  stages_.push_back({plan.inertia ? inertia_stage : elastic_stage, [this] {
                       const CellForceState& f = forces_.state();
                       FsiForceFunctor<NodeVectors, Kokkos::View<double*>> sum{
                           f.elastic,
                           f.interaction,
                           f.wall,
                           excess_mass_,
                           population_.velocities(),
                           state_.previous_velocities,
                           {gravity_[0], gravity_[1], gravity_[2]},
                           state_.previous_dt > 0.0 ? 1.0 / state_.previous_dt : 0.0,
                           state_.fsi_forces};
                       Kokkos::parallel_for("rouleau::ImmersedCoupling::fsi_force",
                                            Kokkos::RangePolicy<ExecSpace>(0, population_.num_nodes()), sum);
                       check_finite_forces(state_.fsi_forces, f.elastic, population_);
                       return true;
                     }});
  // 2. Reads x^n and state_.fsi_forces; writes the RKPM weights at x^n (also those of the
  //    interpolation), state_.fluid_terms (the spread forces and, across ranks, the union of
  //    the ranks' supports, where the fluid replicates and sums) and state_.corrected_points.
  stages_.push_back({spread_stage, [this] {
                       if (shares_) restrict_transfers();
                       update_rkpm_supports(rkpm_, population_);
                       if (fluid_.exchange().spans_ranks())
                         state_.fluid_terms.cell_support_nodes =
                             shares_ ? fluid_.exchange().nodes_of_any_rank(rkpm_.support_nodes())
                                     : Kokkos::View<const int*>(rkpm_.support_nodes());
                       // The cells read u' at their supports only: on one rank it is computed there.
                       if (total_velocity_.extent(0) > 0 && !fluid_.exchange().spans_ranks())
                         state_.fluid_terms.subscale_region =
                             fluid_.fluid_operator().subscale_region_around(rkpm_.support_nodes());
                       state_.felt_terms.cell_support_nodes = state_.fluid_terms.cell_support_nodes;
                       state_.felt_terms.subscale_region = state_.fluid_terms.subscale_region;
                       spread(state_.fsi_forces, fluid_load_);
                       // across ranks each rank counts its own cells' points
                       state_.corrected_points =
                           shares_ ? static_cast<int>(fluid_.exchange().ranks()->sum(
                                         static_cast<long long>(rkpm_.corrected_points())))
                                   : rkpm_.corrected_points();
                       return true;
                     }});
  // 3. Semi-implicit: reads x^n; writes the linearization K about x^n (CellStiffness).
  if (stiffness_)
    stages_.push_back({stiffness_stage, [this] {
                         stiffness_->linearize(population_.positions(), state_.dt);
                         return true;
                       }});
  //    Reads state_.fluid_terms (and K); writes the fluid's state and state_.fluid. The
  //    step ends here when the solve fails.
  stages_.push_back({fluid_stage, [this] {
                       ImmersedTerms terms = state_.fluid_terms;
                       if (stiffness_) {
                         // The cells move with u_h + u' when total_velocity_ is there: Ŝ then acts on it.
                         terms.stiffness = stiffness_.get();
                         terms.stiffness_moves_with_subscale = total_velocity_.extent(0) > 0;
                         terms.stiffness_is_shared = shares_;
                       }
                       state_.fluid = fluid_.advance(state_.dt, state_.scheme, terms);
                       return state_.fluid.converged;
                     }});
  // 4. Reads the fluid's state and state_.fluid_terms; writes state_.cell_carrier (u_h, or
  //    u_h + u' with coupling.subscale_velocity) and state_.global_state, in the global
  //    numbering: the fluid's own vectors on one rank, their global copies at the cells'
  //    supports across ranks.
  stages_.push_back({interpolate_stage, [this] {
                       Kokkos::View<const double*> carrier = fluid_.state(), state = fluid_.state();
                       if (total_velocity_.extent(0) > 0) {
                         fluid_.total_velocity(total_velocity_, state_.fluid_terms);
                         carrier = total_velocity_;
                       }
                       if (fluid_.exchange().spans_ranks()) {
                         const auto& nodes = state_.fluid_terms.cell_support_nodes;
                         fluid_.gather_global(carrier, cell_carrier_, nodes);
                         if (global_state_.extent(0) > 0) fluid_.gather_global(fluid_.state(), global_state_, nodes);
                         state = global_state_.extent(0) > 0 ? global_state_ : cell_carrier_;
                         carrier = cell_carrier_;
                       }
                       state_.cell_carrier = carrier;
                       state_.global_state = state;
                       return true;
                     }});
  //    Semi-implicit: reads state_.cell_carrier, state_.fsi_forces and K; writes
  //    state_.felt_forces = F_I + K Δt I u^{n+1} and state_.felt_terms, their spread.
  if (stiffness_)
    stages_.push_back({stiffness_stage, [this] {
                         stiffness_->force_change(state_.cell_carrier, force_change_);
                         Kokkos::deep_copy(state_.felt_forces, state_.fsi_forces);
                         add_node_vectors(state_.felt_forces, force_change_);
                         spread(state_.felt_forces, felt_load_);
                         return true;
                       }});
  //    Reads state_.cell_carrier and the RKPM weights; writes state_.interpolated (across
  //    ranks each cell's velocities from the rank computing it).
  stages_.push_back({interpolate_stage, [this] {
                       rkpm_.interpolate(state_.cell_carrier, fluid_unknowns_per_node, state_.interpolated);
                       if (shares_) {
                         keep_nodes(state_.interpolated, computed_nodes_);
                         sum_over_ranks(state_.interpolated);
                       }
                       return true;
                     }});
  //    Films: reads state_.interpolated, state_.felt_forces and the positions x^n; writes
  //    state_.cell_velocities (coupling/film_drainage.hpp). The velocities are scaled, so
  //    the films' speeds are too.
  if (films_)
    stages_.push_back({film_stage, [this] {
                         films_->add_opening_velocities(state_.felt_forces, state_.interpolated,
                                                        state_.cell_velocities, state_.dt, fluid_.scales().velocity,
                                                        stiffness_.get());
                         return true;
                       }});
  // 5. Reads state_.cell_velocities; writes the cells' positions and velocities (their one
  //    writer in the step: CellPopulation::move), state_.previous_velocities,
  //    state_.previous_dt, and the step's powers and speeds (the power of the forces the
  //    fluid felt, on the fluid's side and on the cells': they agree, interpolation and
  //    spreading being transposes of each other, except for the power of the films'
  //    opening velocities when the film model runs).
  stages_.push_back({move_stage, [this] {
                       const double largest_speed2 = population_.move(state_.cell_velocities, fluid_.scales().velocity,
                                                                      state_.dt, state_.previous_velocities);
                       state_.previous_dt = state_.dt;
                       state_.finite = largest_speed2 < MoveCellsFunctor<NodeVectors>::non_finite_speed2;
                       state_.largest_cell_speed = std::sqrt(largest_speed2);
                       state_.power_spread = dot(state_.felt_terms.loads, state_.global_state) * fluid_.scales().velocity;
                       state_.power_interpolated = dot(state_.felt_forces, population_.velocities());
                       if (shares_) state_.power_interpolated = fluid_.exchange().ranks()->sum(state_.power_interpolated);
                       return true;
                     }});
}

std::vector<std::string> ImmersedCoupling::stage_names() const {
  std::vector<std::string> names;
  for (const StepStage& stage : stages_) names.push_back(stage.name);
  for (const StepStage& stage : forces_.stages()) names.push_back(stage.name);
  return names;
}

ImmersedCoupling::StepReport ImmersedCoupling::advance(double dt, TimeScheme scheme, bool with_energies,
                                                       StageTimes& times) {
  ProfilingRegion region("rouleau::ImmersedCoupling::advance");
  state_.dt = dt;
  state_.scheme = scheme;
  state_.fluid = FluidSolveReport{};
  // The forces at x^n: the last step's 6, or anew (the cells placed, restored or shared anew).
  if (forces_.stale()) forces_.compute(false, times);
  // 1–5, then 6: the forces at the new positions.
  const bool completed = run_stages(stages_, times);
  if (completed && state_.finite) forces_.compute(with_energies, times);
  StepReport report;
  report.fluid = state_.fluid;
  report.corrected_points = state_.corrected_points;
  if (!completed) return report;
  report.power_spread = state_.power_spread;
  report.power_interpolated = state_.power_interpolated;
  report.largest_cell_speed = state_.largest_cell_speed;
  report.finite = state_.finite;
  return report;
}

void ImmersedCoupling::spread(const NodeVectors& forces, const Kokkos::View<double*>& loads) const {
  Kokkos::deep_copy(loads, 0.0);
  rkpm_.spread(forces, loads, fluid_unknowns_per_node);
  if (shares_) fluid_.exchange().sum_at_nodes(loads, state_.fluid_terms.cell_support_nodes);
}

void ImmersedCoupling::share_cells(const std::vector<int>& cells) {
  if (!fluid_.exchange().spans_ranks())
    throw std::logic_error("rouleau::ImmersedCoupling::share_cells: the fluid is on one rank");
  population_.share_work(cells);
  if (interaction_) interaction_->share_rows(cells);
  std::vector<int> computed(population_.num_nodes(), 0);
  const std::vector<int>& first = population_.cell_first_node();
  const std::vector<int>& count = population_.cell_node_count();
  for (const int c : cells)
    for (int n = first[c]; n < first[c] + count[c]; ++n) computed[n] = 1;
  computed_nodes_ = device_copy(computed, "rouleau::ImmersedCoupling::computed_nodes");
  forces_.share(computed_nodes_);
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
  fluid_.exchange().ranks()->sum(host_node_vectors_.data(), 3 * static_cast<int>(values.extent(0)));
  Kokkos::deep_copy(values, host_node_vectors_);
}

void ImmersedCoupling::save_state(CheckpointData& data) const {
  data.reals["coupling/previous_velocities"] = to_flat_vector(state_.previous_velocities);
  data.reals["coupling/previous_dt"] = {state_.previous_dt};
}

void ImmersedCoupling::restore_state(const CheckpointData& data) {
  from_flat_vector(data.real("coupling/previous_velocities", 3LL * population_.num_nodes()), state_.previous_velocities,
                   "coupling/previous_velocities");
  state_.previous_dt = data.real("coupling/previous_dt", 1).front();
}

}  // namespace rouleau
