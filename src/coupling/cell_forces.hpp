#pragma once
// The forces on the cell nodes at the cells' current positions, each computed by a stage of
// its own: the elastic forces (neo-Hookean, paper eqs. 2, 9, 10, with the global area and
// volume constraints), the Morse interaction between cell surfaces (eqs. 3, 4, 11) and a
// vessel wall's repulsion. The coupled step runs them at its end, on the positions it has
// just moved the cells to, so the next step, the output and the diagnostics all read the
// same forces (and energies, when the step is asked for them) instead of computing them
// again. The scene's plan decides which run (config/scene_plan.hpp).
#include <Kokkos_Core.hpp>
#include <memory>
#include <vector>

#include "cells/cell_population.hpp"
#include "cells/surface_interaction.hpp"
#include "config/case_config.hpp"
#include "config/scene_plan.hpp"
#include "coupling/step_stage.hpp"
#include "coupling/wall_repulsion.hpp"

namespace rouleau {

// What the force stages write; each field names its one writer.
struct CellForceState {
  using NodeVectors = CellPopulation::NodeVectors;
  CellPopulation::ConstNodeVectors elastic;  // "neo-Hookean forces": CellPopulation::internal_forces() [pN]
  NodeVectors interaction;                   // "Morse forces" [pN]; empty without the interaction
  NodeVectors wall;                          // "wall repulsion" [pN]; empty without it
  // With energies asked: Σ_e V0 W(F_e) + E_A + E_V ("neo-Hookean forces") and the Morse
  // energy ("Morse forces"; 0 without the interaction) [pN·μm], this rank's share.
  bool has_energies = false;
  double elastic_energy = 0.0, interaction_energy = 0.0;
};

class CellForces {
 public:
  using NodeVectors = CellPopulation::NodeVectors;
  static constexpr const char* elastic_stage = stage_name::elastic_forces;
  static constexpr const char* interaction_stage = stage_name::interaction_forces;
  static constexpr const char* wall_stage = stage_name::wall_repulsion;

  // `population` and `interaction` (null without one) must outlive it.
  CellForces(CellPopulation& population, SurfaceInteraction* interaction, const CaseConfig& config,
             const ScenePlan& plan);

  // Runs the force stages at the cells' current positions, with the energies when asked.
  void compute(bool with_energies, StageTimes& times);
  // compute() unless the state already holds the forces at the current positions (and the
  // energies, when asked): for the output and diagnostics of a state no step computed (the
  // cells as placed or restored, a steady solve).
  void ensure(bool with_energies, StageTimes& times);
  // The cells were placed, restored or shared anew: the state no longer holds their forces.
  void mark_stale() { stale_ = true; }
  bool stale() const { return stale_; }
  const CellForceState& state() const { return state_; }
  const std::vector<StepStage>& stages() const { return stages_; }

  // The wall's repulsion, or null (the semi-implicit coupling differences it).
  const WallRepulsion* wall() const { return wall_.get(); }
  // With a share of the cells on this rank (ImmersedCoupling::share_cells): the wall's
  // forces at the nodes n with computed_nodes(n) = 1 alone.
  void share(const Kokkos::View<const int*>& computed_nodes) {
    computed_nodes_ = computed_nodes;
    stale_ = true;
  }
  const Kokkos::View<const int*>& computed_nodes() const { return computed_nodes_; }

 private:
  CellPopulation& population_;
  SurfaceInteraction* interaction_;
  std::unique_ptr<WallRepulsion> wall_;
  Kokkos::View<const int*> computed_nodes_;  // share(); empty: every node
  bool with_energies_ = false;               // of the evaluation under way
  bool stale_ = true;                        // mark_stale()
  CellForceState state_;
  std::vector<StepStage> stages_;
};

// sum(n, d) += part(n, d) over the cell nodes.
void add_node_vectors(const CellPopulation::NodeVectors& sum, const CellPopulation::NodeVectors& part);
// v(n) = 0 at the nodes n with computed(n) = 0 (a rank's share of per-node forces).
void keep_nodes(const CellPopulation::NodeVectors& v, const Kokkos::View<const int*>& computed);

}  // namespace rouleau
