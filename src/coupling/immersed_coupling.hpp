#pragma once
// One time step of the immersed finite element method (paper eqs. 5–16) for the cells of a
// case on the fixed fluid mesh, as a list of stages built once from the scene's plan
// (config/scene_plan.hpp) and run in order:
//   1. the forces on the cell nodes at x^n, summed with inertia and buoyancy (eq. 7):
//      F_I = f_elastic + f_Morse + f_wall + (ρ_s − ρ_f) V_I (g − dv/dt);
//   2. spread: F_J = Σ_I Φ_J(x_I^n) F_I (eq. 16), nodal loads on the fluid;
//   3. the fluid solve from t^n to t^{n+1} (eqs. 13, 14), given those loads as an argument;
//   4. interpolate: v_I^{n+1} = Σ_J Φ_J(x_I^n) u_J^{n+1} (eqs. 6, 15);
//   5. move: x_I^{n+1} = x_I^n + Δt v_I^{n+1};
//   6. the forces at x^{n+1} (coupling/cell_forces.hpp), which the next step spreads and
//      the output and diagnostics read.
// With coupling.scheme = "semi_implicit" the fluid solve of step 3 also carries the
// forces' change over the step, linearized about x^n (coupling/cell_stiffness.hpp):
// f^n + K Δt I u^{n+1}; after the solve that change is added to the forces the fluid felt,
// so the reported forces, powers and wall reactions are those of the solve.
// With viscosity ratio 1 the cell's viscous stress is the fluid's and the pressures
// cancel, so ∇·σ_s − ∇·σ_f of eq. (7) is the elastic force alone. Spreading and
// interpolation use the same shape functions, so the power the cells put into the fluid
// equals the power the fluid gives back to round-off; both are reported.
//
// Every field of the step's state (CouplingState) has one writer, the stage named beside
// it; the fluid, the cells' positions and velocities, and the forces have theirs (the
// fluid solve, "move cells", CellForces).
#include <Kokkos_Core.hpp>
#include <memory>
#include <string>
#include <vector>

#include "cells/cells_from_case.hpp"
#include "config/case_config.hpp"
#include "config/scene_plan.hpp"
#include "coupling/cell_forces.hpp"
#include "coupling/cell_stiffness.hpp"
#include "coupling/film_drainage.hpp"
#include "coupling/rkpm_coupler.hpp"
#include "coupling/step_stage.hpp"
#include "fluid/fluid_solver.hpp"
#include "util/stage_times.hpp"

namespace rouleau {

// What one coupled step computes, each field with the stage that writes it.
struct CouplingState {
  using NodeVectors = CellPopulation::NodeVectors;
  // The step asked for (ImmersedCoupling::advance).
  double dt = 0.0;
  TimeScheme scheme = TimeScheme::bdf2;
  // F_I at x^n [pN]: "inertia/buoyancy" (the sum of the force stages' forces and eq. 7's
  // inertia; timed as "neo-Hookean forces" when there is no inertia).
  NodeVectors fsi_forces;
  // F_J, the spread forces on the fluid's unknowns [pN], with how they enter the fluid and
  // the cells' supports: "RKPM spread" (with the RKPM weights at x^n and the count of
  // corrected points).
  ImmersedTerms fluid_terms;
  int corrected_points = 0;
  // The solve's report: "fluid solve".
  FluidSolveReport fluid;
  // The fluid velocity the cells move with (u_h, or u_h + u'), scaled, in the global
  // numbering, and the fluid's state there: "cell velocity" (timed as "RKPM interpolate").
  Kokkos::View<const double*> cell_carrier, global_state;
  // What the fluid felt: F_I + K Δt I u^{n+1} and its spread, "cell stiffness (semi-implicit)";
  // the same Views as fsi_forces and fluid_terms in the explicit coupling.
  NodeVectors felt_forces;
  ImmersedTerms felt_terms;
  // v̂_I, the scaled fluid velocity at the cell nodes: "RKPM interpolate".
  NodeVectors interpolated;
  // The velocity the cells move with, scaled: v̂_I plus the sub-grid films' opening
  // velocities, "film drainage (sub-grid)"; the same View as interpolated without films.
  NodeVectors cell_velocities;
  // v^{n−1} (for dv/dt), the last Δt, and the step's powers and speeds: "move cells".
  NodeVectors previous_velocities;
  double previous_dt = 0.0;
  double power_spread = 0.0;        // Σ_J F_J · u_J^{n+1} [pN·μm/s]
  double power_interpolated = 0.0;  // Σ_I F_I · v_I^{n+1} [pN·μm/s]
  double largest_cell_speed = 0.0;  // max_I |v_I^{n+1}| [μm/s]
  bool finite = true;               // false when some new cell velocity is NaN or Inf
};

class ImmersedCoupling {
 public:
  using NodeVectors = CellPopulation::NodeVectors;

  // The stage names, as timed and printed.
  static constexpr const char* elastic_stage = CellForces::elastic_stage;
  static constexpr const char* interaction_stage = CellForces::interaction_stage;
  static constexpr const char* wall_stage = CellForces::wall_stage;
  static constexpr const char* inertia_stage = stage_name::inertia;
  static constexpr const char* spread_stage = stage_name::spread;
  static constexpr const char* fluid_stage = stage_name::fluid_solve;
  static constexpr const char* interpolate_stage = stage_name::interpolate;
  static constexpr const char* film_stage = stage_name::film_drainage;
  static constexpr const char* move_stage = stage_name::move_cells;
  static constexpr const char* stiffness_stage = stage_name::cell_stiffness;

  // `fluid`, `cells` and `forces` must outlive the coupling. The cells must lie inside the
  // fluid mesh. The stages are those `plan` says run.
  ImmersedCoupling(FluidSolver& fluid, const CaseCells& cells, CellForces& forces, const CaseConfig& config,
                   const ScenePlan& plan);

  struct StepReport {
    FluidSolveReport fluid;
    double power_spread = 0.0;        // Σ_J F_J · u_J^{n+1} [pN·μm/s]
    double power_interpolated = 0.0;  // Σ_I F_I · v_I^{n+1} [pN·μm/s]
    double largest_cell_speed = 0.0;  // max_I |v_I^{n+1}| [μm/s]
    bool finite = true;               // false when some new cell velocity is NaN or Inf
    int corrected_points = 0;         // cell nodes whose RKPM weights needed the correction
  };
  // One step of dt [s]; the fluid advances with `scheme`; the forces at the new positions
  // are computed with their energies when `with_energies`. Throws std::runtime_error
  // naming the stage when a cell node has left the fluid domain or a force is not finite.
  // The cells do not move when the fluid solve fails (the report says so).
  StepReport advance(double dt, TimeScheme scheme, bool with_energies, StageTimes& times);

  // The step's stages in the order they run, the force stages at the new positions last.
  std::vector<std::string> stage_names() const;

  // Checkpoints ("coupling/..." entries): v^{n−1} and the last Δt, for dv/dt of the
  // inertia term. The fluid and the cells keep their own state (save_state of each).
  void save_state(CheckpointData& data) const;
  void restore_state(const CheckpointData& data);

  // With the fluid split across ranks and every cell on every rank: this rank computes the
  // forces of `cells` (ascending, each once: their elastic, wall and inertia forces, and the
  // Morse pairs rooted at their surface points), spreads them, and the fluid sums the ranks'
  // spread forces (and Ŝ's actions) at the cells' supports. The positions stay the same on
  // every rank: each moves every cell with the whole fluid's velocity. The reports'
  // power_interpolated is then summed over the ranks. Called again when cells change rank
  // (Simulation: the rank holding a cell's centroid computes it).
  void share_cells(const std::vector<int>& cells);

  bool runs_interaction() const { return interaction_ != nullptr; }
  bool runs_inertia() const { return excess_mass_.extent(0) > 0; }
  bool runs_wall_repulsion() const { return forces_.wall() != nullptr; }
  bool semi_implicit() const { return stiffness_ != nullptr; }
  // The last step's state (what the fluid felt: state().felt_terms).
  const CouplingState& state() const { return state_; }
  const RkpmCoupler& rkpm() const { return rkpm_; }

 private:
  // Across ranks: marks transferred_nodes_ anew when the share or the Morse list changed,
  // and restricts the RKPM rows to them.
  void restrict_transfers();
  // loads ← S forces (paper eq. 16), summed over the ranks' shares.
  void spread(const NodeVectors& forces, const Kokkos::View<double*>& loads) const;
  // values ← Σ_ranks values (through host memory).
  void sum_over_ranks(const NodeVectors& values);

  FluidSolver& fluid_;
  CellPopulation& population_;
  SurfaceInteraction* interaction_;
  CellForces& forces_;
  RkpmCoupler rkpm_;
  std::array<double, 3> gravity_;  // [μm/s²]
  Kokkos::View<double*> excess_mass_;        // (ρ_s − ρ_f) V_I per node [pN·s²/μm]; the share's nodes' alone
  Kokkos::View<double*> every_excess_mass_;  // the same at every node (share_cells)
  std::unique_ptr<CellStiffness> stiffness_;  // the semi-implicit coupling's K, or null
  std::unique_ptr<FilmDrainage> films_;       // the sub-grid film model, or null
  NodeVectors stiffness_scratch_;             // wall forces while K is differenced
  NodeVectors force_change_;                  // K Δt I u^{n+1} [pN] of the semi-implicit step
  CouplingState state_;
  // The loads' buffers: fluid_load_ (state_.fluid_terms) and felt_load_ (semi-implicit).
  Kokkos::View<double*> fluid_load_, felt_load_;
  // With coupling.subscale_velocity: the fluid's whole velocity u_h + u' (scaled, the rank's
  // local vector), which the cells move with; empty otherwise (they move with u_h).
  Kokkos::View<double*> total_velocity_;
  // Across ranks: the global copies of what the cells move with and of the fluid's state
  // (when the cells move with u_h + u'); empty on one rank, where the fluid's own serve.
  Kokkos::View<double*> cell_carrier_, global_state_;
  bool shares_ = false;                       // share_cells()
  Kokkos::View<int*> computed_nodes_;         // (node): 1 at this rank's cells' nodes (share_cells), else empty
  // Across ranks: the nodes this rank transfers (its cells' and those its Morse pairs
  // reach: the RKPM rows, RkpmCoupler::restrict_rows), marked for list version
  // transferred_list_version_; a host buffer for sums of node vectors over the ranks.
  Kokkos::View<int*> transferred_nodes_;
  int transferred_list_version_ = -1;
  NodeVectors::HostMirror host_node_vectors_;
  std::vector<StepStage> stages_;  // 1–5 of the step; CellForces holds 6
};

}  // namespace rouleau
