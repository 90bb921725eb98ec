#pragma once
// Time integration and nonlinear solution of the fluid (paper eqs. 13–14).
//
// Each solve is Newton–Raphson on the scaled residual R(U) = 0; each Newton step solves
// J δ = −R with right-preconditioned GMRES, J applied element by element (matrix-free).
// In the Stokes limit the residual is affine: one Krylov solve per step.
// Time stepping: backward Euler or BDF2 (BE on the first step), or a steady solve.
//
// Across ranks (a FluidDistribution, issue 10) each rank solves on its part of the mesh:
// its operator completes every element sum across ranks (node sums), GMRES runs on the
// owned unknowns with its reductions over all ranks, and the preconditioner is point-block
// Jacobi across ranks (block_jacobi, the same iterates as one rank) or additive Schwarz
// with ILU(0) or the multigrid per rank (AdditiveSchwarz, for ilu0 and multigrid: the
// answer agrees with one rank's to the solver's tolerance). What the solver takes and gives in the global
// numbering says so; the rest is the rank's local vectors (state(), total_velocity()).
#include <Kokkos_Core.hpp>
#include <functional>
#include <memory>
#include <string>

#include "config/case_config.hpp"
#include "distributed/distributed_fluid_operator.hpp"
#include "distributed/fluid_distribution.hpp"
#include "distributed/additive_schwarz.hpp"
#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_operator.hpp"
#include "fluid/fluid_matrix.hpp"
#include "io/checkpoint_file.hpp"
#include "solver/block_jacobi.hpp"
#include "solver/aggregation_multigrid.hpp"
#include "solver/ilu0_preconditioner.hpp"
#include "solver/gmres.hpp"

namespace rouleau {

struct FluidSolveReport {
  bool converged = false;
  int newton_iterations = 0;
  int gmres_iterations = 0;          // summed over Newton steps
  double initial_residual = 0.0;     // ‖R(U₀)‖ (scaled)
  double momentum_residual = 0.0;    // ‖R‖ over velocity rows at the end
  double continuity_residual = 0.0;  // ‖R‖ over pressure rows at the end
  bool stalled_at_round_off = false;  // converged on ‖δ‖ ≤ newton_step_rtol ‖U‖, not on ‖R‖
  std::string failure;               // why it did not converge
};

class FluidSolver {
 public:
  // `stokes`: drop convection (the Stokes limit). Scales from derive_quantities().
  // `distribution`: the ranks the solve is split across (it must outlive the solver), or
  // null for one rank; `mesh` is the whole mesh either way.
  FluidSolver(const FluidMesh& mesh, const FluidConfig& fluid, const std::vector<FluidBoundary>& boundaries,
              const SolverConfig& settings, const FluidScales& scales, bool stokes,
              const FluidDistribution* distribution = nullptr);
  // A box's six sides.
  FluidSolver(const FluidMesh& mesh, const FluidConfig& fluid, const std::array<BoundaryConfig, 6>& sides,
              const SolverConfig& settings, const FluidScales& scales, bool stokes)
      : FluidSolver(mesh, fluid, box_boundaries(sides), settings, scales, stokes) {}

  // Solves the steady equations from the current state.
  FluidSolveReport solve_steady();
  // Advances by dt [s] with the given scheme (BDF2 falls back to BE on the first step).
  FluidSolveReport advance(double dt, TimeScheme scheme);

  // The body force density field at the dof nodes [pN/μm³], size 3·num_dof_nodes of the
  // whole mesh, host.
  void set_body_force(const std::vector<double>& force_density);
  // Constant body force density everywhere [pN/μm³].
  void set_uniform_body_force(const std::array<double, 3>& force_density);

  // Nodal forces [pN] on the fluid's unknowns in the global numbering (num_global_unknowns(),
  // node-interleaved like the state, velocity entries read): the cells' forces spread by RKPM (paper eq. 16). They enter the
  // momentum residual as nodal loads (the exact transpose of interpolation) and, when
  // turned on, the stabilization's strong residual as the force density they stand for
  // (FluidOperator::load_stabilization; without it PSPG drives a flux τ ∇p through cells).
  void set_immersed_forces(const ConstVector& nodal_forces);
  void set_immersed_forces_in_stabilization(bool in_stabilization);

  // The semi-implicit coupling's linearized cell forces: an operator Ŝ on the scaled state
  // whose action Ŝ U enters the residual, R(U) = R_fluid(U) + Ŝ U, and so the Jacobian,
  // J = J_fluid + Ŝ (zero on the constrained rows; Ŝ acts on global vectors), with the stabilization's share
  // −P(Ŝ U) of that change of the loads when the immersed forces are in the
  // stabilization. ImmersedCoupling passes Ŝ U = −S K I (Δt U) / (P L²)
  // (coupling/cell_stiffness.hpp); null turns it off. The operator must outlive its use;
  // the preconditioner does not see it. When the cells move with the whole velocity
  // u_h + u' (`moves_with_subscale`), Ŝ acts on that instead of on U's velocity: the
  // residual gains Ŝ (U + u'(U)) and the Jacobian Ŝ (δ + u'_δ), u'_δ the derivative of u'
  // along δ with τ frozen (FluidOperator::subscale_velocity_action), so the forces the
  // fluid solves with are those of the motion total_velocity() gives the cells.
  void set_immersed_stiffness(const LinearOperator* stiffness, bool moves_with_subscale = false);

  // Sets the velocity everywhere to velocity(x) [μm/s] at the nodes x [μm] (an initial
  // condition; Dirichlet values are imposed again afterwards).
  void set_velocity(const std::function<std::array<double, 3>(const std::array<double, 3>&)>& velocity);

  // Replaces the prescribed velocity on every Dirichlet velocity unknown by
  // velocity(x) [μm/s] at the node's position x [μm] (manufactured solutions, custom inflows).
  void prescribe_boundary_velocity(const std::function<std::array<double, 3>(const std::array<double, 3>&)>& velocity);

  // Forces [pN] that the fluid exerts on each of the boundary `sides` (walls), from the
  // consistent nodal reactions: the residual at the constrained nodes before the
  // constraint rows (one residual evaluation for all sides).
  std::vector<std::array<double, 3>> boundary_forces(const std::vector<std::string>& sides) const;
  // The fluid's whole velocity u_h + u' (scaled, node-interleaved like the state; the
  // pressure entries are the state's): u' = −τ_M r, PSPG's subscale velocity at the
  // current state, projected onto the nodes (FluidOperator::subscale_velocity).
  void total_velocity(const Vector& out) const;
  // Volume average of the velocity [μm/s].
  std::array<double, 3> mean_velocity() const;
  // Kinetic energy of the fluid ½ ρ ∫ |u|² dV [pN·μm].
  double kinetic_energy() const;
  // {∫ dV, ∫ u dV, ∫ |u|² dV} in scaled variables (x/L, u/U).
  std::array<double, 5> velocity_integrals() const;

  // The unknowns of the whole mesh, and a global copy of a local vector (state(),
  // total_velocity()): the same on every rank (FluidDistribution::replicate).
  int num_global_unknowns() const { return num_global_unknowns_; }
  void gather_global(const ConstVector& local, const Vector& global) const;
  // Across ranks: the global dof nodes whose values the cells read and load (their RKPM
  // supports, ascending): gather_global() and the immersed stiffness then replicate these
  // alone, and leave the other entries of their global vectors as they were. Empty (the
  // default): every node.
  void set_replicated_nodes(const Kokkos::View<const int*>& nodes) { replicated_nodes_ = nodes; }
  // Across ranks, when each rank computes a share of the cells (ImmersedCoupling::
  // share_cells): global ← Σ_ranks global at the replicated nodes, for the forces the
  // rank's cells spread; and Ŝ's action is then summed the same way inside the solve.
  void sum_over_ranks(const Vector& global) const;
  void set_immersed_shares(bool shares) { immersed_shares_ = shares; }
  // The ranks, or null on one rank.
  const FluidDistribution* distribution() const { return distribution_; }

  double time() const { return time_; }
  int steps() const { return steps_; }

  // Checkpoints: the state the next step needs ("fluid/..." entries): U^n, U^{n−1} (BDF2),
  // the time and the step count. The preconditioner is rebuilt from them (in the Stokes
  // limit the Jacobian does not depend on the state; otherwise it is rebuilt every Newton
  // step), so a restarted run repeats the straight one bit for bit.
  void save_state(CheckpointData& data) const;
  // Throws std::runtime_error naming the entry when one is missing or of the wrong size.
  void restore_state(const CheckpointData& data);

  // The rank's operator, on its part of the mesh (the whole mesh on one rank).
  const FluidOperator& fluid_operator() const { return operator_; }
  // The whole mesh.
  const FluidMesh& mesh() const { return mesh_; }
  // Lets the Stokes operator run as the uniform-box stencil where the mesh allows it
  // (FluidOperator::allow_stencil; on by default).
  void allow_stencil(bool allow) { operator_.allow_stencil(allow); }
  const FluidScales& scales() const { return scales_; }
  bool stokes() const { return stokes_; }
  // The scaled state (u/U, p/P interleaved per dof node), the rank's local vector.
  const Vector& state() const { return state_; }
  // Velocity [μm/s] and pressure [Pa] at the geometric nodes of the whole mesh (host arrays,
  // node-major; on every rank).
  void velocity_and_pressure(std::vector<double>& velocity, std::vector<double>& pressure) const;

 private:
  FluidSolveReport solve(const ConstVector& history);
  // The operator's coefficients for a BDF mass coefficient α0/Δt and 1/Δt (scaled; 0, 0: steady).
  void set_time_coefficients(double mass_coefficient, double inverse_dt);
  // y += Ŝ c(x), the immersed stiffness's action on the velocity c(x) the cells move
  // with, left out of the constrained rows when `skip_constrained` (Jacobian and residual
  // rows that hold the boundary conditions). c(x) = x, or with the subscale velocity
  // x + u'(x) for the state (a residual) and x + u'_x for a direction (a Jacobian action).
  enum class StiffnessArgument { state, direction };
  void add_immersed_stiffness(const ConstVector& x, const Vector& y, bool skip_constrained,
                              StiffnessArgument argument) const;
  // Rebuilds the configured preconditioner from the Jacobian at the current state.
  void rebuild_preconditioner();
  const Preconditioner& preconditioner() const;
  // The unknowns GMRES works on: the rank's owned ones (all on one rank).
  int owned_unknowns() const;
  // ‖x‖ over the unknowns of the whole mesh (each once).
  double norm(const ConstVector& x) const;
  // The global vector of a local one as a flat host array (checkpoints).
  std::vector<double> global_values(const ConstVector& local) const;

  const FluidDistribution* distribution_;  // null on one rank
  FluidMesh mesh_;                         // the whole mesh
  int num_global_unknowns_;
  FluidOperator operator_;                 // on the rank's part of the mesh
  FluidScales scales_;
  SolverConfig settings_;
  bool stokes_;
  FluidBoundaryConditions boundary_;
  Vector state_, previous_state_, older_state_, history_, body_force_, correction_, blocks_;
  double density_;                 // ρ [pN·s²/μm⁴]
  Vector immersed_load_;           // the immersed forces (scaled), when there are cells
  const LinearOperator* immersed_stiffness_ = nullptr;  // Ŝ of the semi-implicit coupling, or null
  Vector stiffness_action_, stiffness_stabilization_;  // Ŝ x and P(Ŝ x) (scratch)
  bool stiffness_moves_with_subscale_ = false;         // Ŝ acts on x + u' (set_immersed_stiffness)
  Vector stiffness_carrier_;                           // x + u' (scratch)
  Vector residual_;  // also scratch for boundary_forces() (const)
  Vector state_gradient_;  // G(U) during a Krylov solve
  BlockJacobi block_jacobi_;
  IdentityPreconditioner identity_;
  FluidMatrixGraph matrix_graph_;               // ILU(0), multigrid: the assembled Jacobian's graph,
  Vector matrix_values_;                        // its values,
  std::unique_ptr<Ilu0Preconditioner> ilu0_;    // and the factorization
  std::unique_ptr<AggregationMultigrid> multigrid_;  // or the hierarchy
  // Across ranks: the preconditioners on the owned unknowns, and scratch for the
  // Jacobian's lift of owned vectors to local ones and for Ŝ's global vectors.
  std::unique_ptr<DistributedBlockJacobi> distributed_jacobi_;
  std::unique_ptr<AdditiveSchwarz> additive_schwarz_;
  Vector lifted_direction_, lifted_action_, global_carrier_, global_action_;
  Kokkos::View<const int*> replicated_nodes_;  // set_replicated_nodes()
  bool immersed_shares_ = false;               // set_immersed_shares()
  Gmres gmres_;
  bool preconditioner_current_ = false;  // Stokes: J is constant while dt is
  double last_mass_coefficient_ = -1.0;
  double time_ = 0.0;
  int steps_ = 0;
};

}  // namespace rouleau
