#pragma once
// A case built and ready to step: the fluid mesh and solver, the cells and their
// interaction, the immersed coupling, and the stage times. run_case() drives one with
// output around it; tests and case drivers drive one directly and read its state.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cells/cells_from_case.hpp"
#include "config/case_config.hpp"
#include "config/scene_plan.hpp"
#include "coupling/cell_forces.hpp"
#include "coupling/immersed_coupling.hpp"
#include "fluid/fluid_solver.hpp"
#include "distributed/fluid_distribution.hpp"
#include "mesh/fluid_mesh.hpp"
#include "parallel/communicator.hpp"
#include "util/stage_times.hpp"

namespace rouleau {

class Simulation {
 public:
  // Builds the stages the scene's plan (config/scene_plan.hpp) says run, and what they
  // need (cell meshes from `mesh_cache_dir`). The case must have been loaded by
  // load_case() (so it is valid). With `ranks` of more than one rank the fluid is split
  // across them (FluidDistribution) and every rank
  // holds every cell and computes the forces of the cells whose centroid it holds
  // (FluidDistribution::rank_holding, ImmersedCoupling::share_cells; decided anew before
  // every step, so a cell whose centroid crosses into another rank's part moves its work
  // there); the cells read the fluid at their supports, replicated from the nodes' owners,
  // and the ranks' spread forces are summed there. All ranks must build it together.
  Simulation(const CaseConfig& config, const std::string& mesh_cache_dir, const Communicator* ranks = nullptr);

  // One time step of config.time.dt: the coupled step when there are cells, the fluid
  // alone otherwise. Throws DivergenceError naming the step, the stage and the values
  // when the fluid solve fails, a cell node leaves the fluid or its velocity is not
  // finite, or a cell's enclosed volume has changed by more than
  // coupling.volume_tolerance of its initial volume. With `with_energies` the forces at the
  // new positions come with the elastic and interaction energies (diagnostics rows).
  const ImmersedCoupling::StepReport& advance(bool with_energies = false);
  // The steady solve (cells, if any, stay in place). Throws DivergenceError on failure.
  const ImmersedCoupling::StepReport& solve_steady();

  // Checkpoints: the step, the time and the state of the fluid, the cells, their
  // interaction list and the coupling, plus the stage times. Restoring needs a Simulation
  // built from the same case (the caller checks the meshes' hashes) and throws
  // std::runtime_error naming a missing or mis-sized entry.
  void save_state(CheckpointData& data) const;
  void restore_state(const CheckpointData& data);

  int steps() const { return steps_; }
  double time() const { return fluid_->time(); }
  const CaseConfig& config() const { return config_; }
  const DerivedQuantities& derived() const { return derived_; }
  const FluidMesh& mesh() const { return mesh_; }
  FluidSolver& fluid() { return *fluid_; }
  const FluidSolver& fluid() const { return *fluid_; }
  const CaseCells& cells() const { return cells_; }
  const ScenePlan& plan() const { return plan_; }
  // The forces on the cell nodes at their current positions (with the energies when
  // asked), as the last step computed them, or computed now when no step has (the cells as
  // placed or restored, a steady solve). Only with cells.
  const CellForceState& cell_forces(bool with_energies);
  // Places the cells' nodes at `positions` [μm] (node-major), as a driver or a test moves
  // them between steps; the next step computes their forces anew.
  void set_cell_positions(const Kokkos::View<const double* [3], Kokkos::HostSpace>& positions);
  // The fluid's split across the ranks, or null on one rank.
  const FluidDistribution* distribution() const { return distribution_.get(); }
  // The coupling, or nullptr (no cells, or a steady case).
  ImmersedCoupling* coupling() { return coupling_.get(); }
  const ImmersedCoupling* coupling() const { return coupling_.get(); }
  const ImmersedCoupling::StepReport& last_report() const { return last_report_; }
  // Across ranks: the rank computing each cell (the rank holding its centroid), and how many
  // times a cell has changed rank since this Simulation was built. Empty and 0 otherwise.
  const std::vector<int>& cell_ranks() const { return cell_ranks_; }
  int cell_rank_changes() const { return cell_rank_changes_; }
  StageTimes& times() { return times_; }
  const StageTimes& times() const { return times_; }

 private:
  [[noreturn]] void diverged(const std::string& stage, const std::string& what) const;
  // Stop (diverged) when the fluid solve failed or its state holds a NaN or Inf (naming
  // the first such unknown, and the solver's failure when there is one).
  void check_fluid_solve() const;
  void check_fluid_state() const;
  // Stop (diverged) when a cell element is inverted (J = det F ≤ 0), naming it and its cell.
  void check_cell_elements() const;
  // Across ranks: each cell to the rank holding its centroid (cell_ranks_); the coupling's
  // share is set anew when a cell changed rank.
  void assign_cells_to_ranks();

  CaseConfig config_;
  DerivedQuantities derived_;
  ScenePlan plan_;
  StageTimes times_;
  FluidMesh mesh_;
  std::unique_ptr<FluidDistribution> distribution_;  // several ranks, or null
  std::unique_ptr<FluidSolver> fluid_;
  CaseCells cells_;
  std::unique_ptr<CellForces> cell_forces_;  // with cells
  std::unique_ptr<ImmersedCoupling> coupling_;
  ImmersedCoupling::StepReport last_report_;
  std::vector<double> initial_volumes_;  // each cell's enclosed volume as placed [μm³]
  std::vector<int> cell_ranks_;          // assign_cells_to_ranks()
  int cell_rank_changes_ = 0;
  int steps_ = 0;
};

// The fluid mesh a case describes: a box of hexahedra, periodic where the case says, or a
// vessel's lumen of tetrahedra (Gmsh, cached in `mesh_cache_dir`).
FluidMesh make_case_mesh(const CaseConfig& config, const std::string& mesh_cache_dir);

}  // namespace rouleau
