#include "coupling/cell_forces.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
}  // namespace

void add_node_vectors(const CellPopulation::NodeVectors& sum, const CellPopulation::NodeVectors& part) {
  Kokkos::parallel_for(
      "rouleau::add_node_vectors", Kokkos::RangePolicy<ExecSpace>(0, sum.extent(0)), KOKKOS_LAMBDA(const int n) {
        for (int d = 0; d < 3; ++d) sum(n, d) += part(n, d);
      });
}

void keep_nodes(const CellPopulation::NodeVectors& v, const Kokkos::View<const int*>& computed) {
  Kokkos::parallel_for(
      "rouleau::keep_nodes", Kokkos::RangePolicy<ExecSpace>(0, v.extent(0)), KOKKOS_LAMBDA(const int n) {
        if (!computed(n))
          for (int d = 0; d < 3; ++d) v(n, d) = 0.0;
      });
}

CellForces::CellForces(CellPopulation& population, SurfaceInteraction* interaction, const CaseConfig& config,
                       const ScenePlan& plan)
    : population_(population), interaction_(plan.morse_forces ? interaction : nullptr) {
  const int nodes = population_.num_nodes();
  state_.elastic = population_.internal_forces();

  // Reads the positions; writes state_.elastic (the population's internal forces) and,
  // with energies, state_.elastic_energy.
  stages_.push_back({elastic_stage, [this] {
                       if (with_energies_)
                         state_.elastic_energy = population_.compute_internal_forces_and_energy();
                       else
                         population_.compute_internal_forces();
                       return true;
                     }});
  if (interaction_) {
    state_.interaction = NodeVectors("rouleau::CellForces::interaction", nodes);
    // Reads the positions; writes the Morse list (rebuilt when a point moved more than half
    // the skin, or every step without skips), state_.interaction and, with energies,
    // state_.interaction_energy.
    const bool rebuild_every_step = plan.rebuild_morse_list_every_step;
    stages_.push_back({interaction_stage, [this, rebuild_every_step] {
                         if (rebuild_every_step) interaction_->rebuild();
                         if (with_energies_)
                           state_.interaction_energy = interaction_->compute_forces_and_energy();
                         else
                           interaction_->compute_forces();
                         interaction_->copy_forces_to_nodes(state_.interaction);
                         return true;
                       }});
  }
  if (plan.wall_repulsion) {
    wall_ = std::make_unique<WallRepulsion>(config.vessel.profile, config.vessel.wall_repulsion_pressure,
                                            config.vessel.wall_repulsion_range);
    state_.wall = NodeVectors("rouleau::CellForces::wall", nodes);
    // Reads the positions; writes state_.wall (this rank's share's nodes alone when shared).
    stages_.push_back({wall_stage, [this] {
                         wall_->compute_forces(population_.positions(), population_.surface_area_weights(),
                                               state_.wall);
                         if (computed_nodes_.extent(0) > 0) keep_nodes(state_.wall, computed_nodes_);
                         return true;
                       }});
  }
}

void CellForces::compute(const bool with_energies, StageTimes& times) {
  with_energies_ = with_energies;
  run_stages(stages_, times);
  state_.has_energies = with_energies;
  stale_ = false;
}

void CellForces::ensure(const bool with_energies, StageTimes& times) {
  if (stale_ || (with_energies && !state_.has_energies)) compute(with_energies, times);
}

}  // namespace rouleau
