#pragma once
// One explicit step of the immersed finite element method (DESIGN.md, "One time step";
// paper eqs. 5–16), for the cells of a case on the fixed fluid mesh:
//   1. forces on the cell nodes at x^n, each its own stage: elastic (neo-Hookean, eqs. 2,
//      9, 10), Morse between cells (eqs. 3, 4, 11), a vessel wall's repulsion, inertia and
//      buoyancy (eq. 7);
//   2. spread: F_J = Σ_I Φ_J(x_I^n) F_I (eq. 16), nodal loads on the fluid;
//   3. the fluid solve from t^n to t^{n+1} (eqs. 13, 14);
//   4. interpolate: v_I^{n+1} = Σ_J Φ_J(x_I^n) u_J^{n+1} (eqs. 6, 15);
//   5. move: x_I^{n+1} = x_I^n + Δt v_I^{n+1}.
// With coupling.scheme = "semi_implicit" the fluid solve of step 3 also carries the
// forces' change over the step, linearized about x^n (coupling/cell_stiffness.hpp):
// f^n + K Δt I u^{n+1}; after the solve that change is added to the spread forces, so the
// reported forces, powers and wall reactions are those the fluid felt.
// With viscosity ratio 1 the cell's viscous stress is the fluid's and the pressures
// cancel, so ∇·σ_s − ∇·σ_f of eq. (7) is the elastic force alone (DESIGN.md). Spreading
// and interpolation use the same shape functions, so the power the cells put into the
// fluid equals the power the fluid gives back to round-off; both are reported.
#include <Kokkos_Core.hpp>
#include <memory>
#include <string>

#include "cells/cells_from_case.hpp"
#include "config/case_config.hpp"
#include "coupling/cell_stiffness.hpp"
#include "coupling/rkpm_coupler.hpp"
#include "coupling/wall_repulsion.hpp"
#include "fluid/fluid_solver.hpp"
#include "run/stage_times.hpp"

namespace rouleau {

class ImmersedCoupling {
 public:
  using NodeVectors = CellPopulation::NodeVectors;

  // The stage names, as timed and printed.
  static constexpr const char* elastic_stage = "neo-Hookean forces";
  static constexpr const char* interaction_stage = "Morse forces";
  static constexpr const char* wall_stage = "wall repulsion";
  static constexpr const char* inertia_stage = "inertia/buoyancy";
  static constexpr const char* spread_stage = "RKPM spread";
  static constexpr const char* fluid_stage = "fluid solve";
  static constexpr const char* interpolate_stage = "RKPM interpolate";
  static constexpr const char* move_stage = "move cells";
  static constexpr const char* stiffness_stage = "cell stiffness (semi-implicit)";

  // `fluid` and `cells` must outlive the coupling. The cells must lie inside the fluid mesh.
  ImmersedCoupling(FluidSolver& fluid, const CaseCells& cells, const CaseConfig& config);

  struct StepReport {
    FluidSolveReport fluid;
    double power_spread = 0.0;        // Σ_J F_J · u_J^{n+1} [pN·μm/s]
    double power_interpolated = 0.0;  // Σ_I F_I · v_I^{n+1} [pN·μm/s]
    double largest_cell_speed = 0.0;  // max_I |v_I^{n+1}| [μm/s]
    bool finite = true;               // false when some new cell velocity is NaN or Inf
    int corrected_points = 0;         // cell nodes whose RKPM weights needed the correction
  };
  // One step of dt [s]; the fluid advances with `scheme`. Throws std::runtime_error naming
  // the stage when a cell node has left the fluid domain. The cells do not move when the
  // fluid solve fails (the report says so).
  StepReport advance(double dt, TimeScheme scheme, StageTimes& times);

  // Checkpoints ("coupling/..." entries): v^{n−1} and the last Δt, for dv/dt of the
  // inertia term. The fluid and the cells keep their own state (save_state of each).
  void save_state(CheckpointData& data) const;
  void restore_state(const CheckpointData& data);

  // With the fluid split across ranks and every cell on every rank (issue 10): this rank
  // computes the forces of `cells` (ascending, each once: their elastic, wall and inertia
  // forces, and the Morse pairs rooted at their surface points), spreads them, and the
  // fluid sums the ranks' spread forces (and Ŝ's actions) at the cells' supports. The
  // positions stay the same on every rank: each moves every cell with the whole fluid's
  // velocity. The reports' power_interpolated is then summed over the ranks. Called again
  // when cells change rank (Simulation: the rank holding a cell's centroid computes it).
  void share_cells(const std::vector<int>& cells);

  bool runs_interaction() const { return interaction_ != nullptr; }
  bool runs_inertia() const { return runs_inertia_; }
  bool runs_wall_repulsion() const { return wall_ != nullptr; }
  bool semi_implicit() const { return stiffness_ != nullptr; }
  // F_I of the last step [pN] (the sum of the stages' forces) and the Morse part alone.
  const NodeVectors& fsi_forces() const { return fsi_forces_; }
  const NodeVectors& interaction_forces() const { return interaction_forces_; }
  const RkpmCoupler& rkpm() const { return rkpm_; }

 private:
  // Across ranks: marks transferred_nodes_ anew when the share or the Morse list changed,
  // and restricts the RKPM rows to them.
  void restrict_transfers();
  // values ← Σ_ranks values (through host memory).
  void sum_over_ranks(const NodeVectors& values);

  FluidSolver& fluid_;
  CellPopulation& population_;
  SurfaceInteraction* interaction_;
  std::unique_ptr<WallRepulsion> wall_;    // a vessel with wall_repulsion_Pa > 0
  RkpmCoupler rkpm_;
  bool skip_unneeded_;
  bool runs_inertia_ = false;
  std::array<double, 3> gravity_;  // [μm/s²]
  double previous_dt_ = 0.0;
  Kokkos::View<double*> excess_mass_;      // (ρ_s − ρ_f) V_I per node [pN·s²/μm]; the share's nodes' alone
  Kokkos::View<double*> every_excess_mass_;  // the same at every node (share_cells)
  NodeVectors previous_velocities_;        // v^{n−1}, for dv/dt
  NodeVectors interaction_forces_, wall_forces_, fsi_forces_;
  NodeVectors interpolated_;               // v̂_I, the scaled fluid velocity at the nodes
  // The cells see the whole fluid in the global numbering (on every rank, when the fluid
  // is split across ranks and the cells are on each of them).
  Kokkos::View<double*> fluid_load_;       // the spread forces on the fluid's unknowns [pN]
  // With coupling.subscale_velocity: the fluid's whole velocity u_h + u' (scaled, like the
  // fluid's state, the rank's local vector), which the cells move with; empty otherwise
  // (they move with u_h).
  Kokkos::View<double*> total_velocity_;
  // Across ranks: what the cells move with and the fluid's state (when the cells move with
  // u_h + u'), global (scaled); empty on one rank, where the fluid's own vectors serve.
  Kokkos::View<double*> cell_carrier_;
  Kokkos::View<double*> global_state_;
  std::unique_ptr<CellStiffness> stiffness_;  // the semi-implicit coupling's K, or null
  bool shares_ = false;                       // share_cells()
  Kokkos::View<int*> computed_nodes_;         // (node): 1 at this rank's cells' nodes (share_cells), else empty
  // Across ranks: the nodes this rank transfers (its cells' and those its Morse pairs
  // reach: the RKPM rows, RkpmCoupler::restrict_rows), marked for list version
  // transferred_list_version_; a host buffer for sums of node vectors over the ranks.
  Kokkos::View<int*> transferred_nodes_;
  int transferred_list_version_ = -1;
  NodeVectors::HostMirror host_node_vectors_;
  NodeVectors stiffness_scratch_;           // interaction or wall forces while K is differenced
  NodeVectors force_change_;                // K Δt I u^{n+1} [pN] of the semi-implicit step
};

}  // namespace rouleau
