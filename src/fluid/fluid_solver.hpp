#pragma once
// Time integration and nonlinear solution of the fluid (paper eqs. 13–14).
//
// Each solve is Newton–Raphson on the scaled residual R(U) = 0; each Newton step solves
// J δ = −R with right-preconditioned GMRES, J applied element by element (matrix-free).
// In the Stokes limit the residual is affine: one Krylov solve per step, started from the
// combination of the last solutions with the least residual (fluid_starting_guess.cpp).
// Time stepping: backward Euler or BDF2 (BE on the first step), or a steady solve.
//
// The ranks are known only through a FluidExchange (fluid/fluid_exchange.hpp), the
// identity on one rank: each rank solves on its part of the mesh, its operator completes
// every element sum across ranks, GMRES runs on the owned unknowns with its reductions
// over all ranks, and the exchange provides the preconditioner. What the solver takes and
// gives in the global numbering says so; the rest is the rank's local vectors (state(),
// total_velocity()).
#include <Kokkos_Core.hpp>
#include <functional>
#include <memory>
#include <string>

#include "config/case_config.hpp"
#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_exchange.hpp"
#include "fluid/fluid_operator.hpp"
#include "fluid/fluid_preconditioner.hpp"
#include "fluid/immersed_terms.hpp"
#include "io/checkpoint_file.hpp"
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
  // `exchange`: the ranks the solve is split across (it must outlive the solver), or
  // null for one rank; `mesh` is the whole mesh either way.
  FluidSolver(const FluidMesh& mesh, const FluidConfig& fluid, const std::vector<FluidBoundary>& boundaries,
              const SolverConfig& settings, const FluidScales& scales, bool stokes,
              const FluidExchange* exchange = nullptr);
  // A box's six sides.
  FluidSolver(const FluidMesh& mesh, const FluidConfig& fluid, const std::array<BoundaryConfig, 6>& sides,
              const SolverConfig& settings, const FluidScales& scales, bool stokes)
      : FluidSolver(mesh, fluid, box_boundaries(sides), settings, scales, stokes) {}

  // Solves the steady equations from the current state, with the cells' `immersed` terms.
  FluidSolveReport solve_steady(const ImmersedTerms& immersed = {});
  // Advances by dt [s] with the given scheme (BDF2 falls back to BE on the first step),
  // with the cells' `immersed` terms (their spread forces, and their linearized stiffness in
  // the semi-implicit coupling).
  FluidSolveReport advance(double dt, TimeScheme scheme, const ImmersedTerms& immersed = {});

  // The body force density field at the dof nodes [pN/μm³], size 3·num_dof_nodes of the
  // whole mesh, host.
  void set_body_force(const std::vector<double>& force_density);
  // Constant body force density everywhere [pN/μm³].
  void set_uniform_body_force(const std::array<double, 3>& force_density);

  // Sets the velocity everywhere to velocity(x) [μm/s] at the nodes x [μm] (an initial
  // condition; Dirichlet values are imposed again afterwards).
  void set_velocity(const std::function<std::array<double, 3>(const std::array<double, 3>&)>& velocity);

  // Replaces the prescribed velocity on every Dirichlet velocity unknown by
  // velocity(x) [μm/s] at the node's position x [μm] (manufactured solutions, custom inflows).
  void prescribe_boundary_velocity(const std::function<std::array<double, 3>(const std::array<double, 3>&)>& velocity);

  // Forces [pN] that the fluid exerts on each of the boundary `sides` (walls), from the
  // consistent nodal reactions: the residual at the constrained nodes before the
  // constraint rows (one residual evaluation for all sides), with the cells' spread forces
  // `immersed.loads` (those the last step's fluid felt).
  std::vector<std::array<double, 3>> boundary_forces(const std::vector<std::string>& sides,
                                                     const ImmersedTerms& immersed = {});
  // The fluid's whole velocity u_h + u' (scaled, node-interleaved like the state; the
  // pressure entries are the state's): u' = −τ_M r, PSPG's subscale velocity at the
  // current state with the cells' `immersed` loads, projected onto the nodes
  // (FluidOperator::subscale_velocity); exact only within immersed.subscale_region when it
  // is restricted.
  void total_velocity(const Vector& out, const ImmersedTerms& immersed = {});
  // Volume average of the velocity [μm/s].
  std::array<double, 3> mean_velocity() const;
  // Kinetic energy of the fluid ½ ρ ∫ |u|² dV [pN·μm].
  double kinetic_energy() const;
  // {∫ dV, ∫ u dV, ∫ |u|² dV} in scaled variables (x/L, u/U).
  std::array<double, 5> velocity_integrals() const;

  // The unknowns of the whole mesh, and a global copy of a local vector (state(),
  // total_velocity()): the same on every rank (FluidExchange::replicate); across
  // ranks at the global dof nodes `nodes` alone when given (the cells' supports: the
  // other entries of `global` are left as they were).
  int num_global_unknowns() const { return num_global_unknowns_; }
  void gather_global(const ConstVector& local, const Vector& global, const Kokkos::View<const int*>& nodes = {}) const;
  // The ranks (the identity's exchange on one rank).
  const FluidExchange& exchange() const { return *exchange_; }

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
  FluidSolveReport solve(const ConstVector& history, const ImmersedTerms& immersed);
  // One Newton step from the residual R in residual_: J δ = −R solved by GMRES to `forcing`
  // on the owned unknowns (the copies follow), U += δ, and R(U) at the new state in
  // residual_.
  GmresResult newton_step(const ImmersedTerms& immersed, bool linear, double forcing);
  // R(U) at the current state into residual_, with the immersed stiffness's share.
  // `constrained_rows`: the Dirichlet rows hold the constraints (the stiffness left out of
  // them); false leaves the nodal reactions there (boundary_forces()). `affine`: the
  // residual is the Stokes step's, R(U) = A U + R(0), with R(0) in zero_state_residual_.
  void residual_at_state(const ImmersedTerms& immersed, bool constrained_rows, bool affine = false);
  // The debug log's line for a Newton step.
  void log_newton_step(const FluidSolveReport& report, const GmresResult& g, double forcing, double residual_norm,
                       double target) const;
  // The operator's immersed load b = F / (P L²) from `immersed.loads` (at the rank's
  // nodes), or none.
  void load_immersed_forces(const ImmersedTerms& immersed);
  // The scratch vectors of add_immersed_stiffness, allocated at the first solve with cells.
  void allocate_stiffness_scratch(const ImmersedTerms& immersed);
  // The operator's coefficients for a BDF mass coefficient α0/Δt and 1/Δt (scaled; 0, 0: steady).
  void set_time_coefficients(double mass_coefficient, double inverse_dt);
  // y += Ŝ c(x), the immersed stiffness's action on the velocity c(x) the cells move
  // with, left out of the constrained rows when `skip_constrained` (Jacobian and residual
  // rows that hold the boundary conditions). c(x) = x, or with the subscale velocity
  // x + u'(x) for the state (a residual) and x + u'_x for a direction (a Jacobian action).
  enum class StiffnessArgument { state, direction };
  void add_immersed_stiffness(const ImmersedTerms& immersed, const ConstVector& x, const Vector& y,
                              bool skip_constrained, StiffnessArgument argument) const;
  // Rebuilds the configured preconditioner from the Jacobian at the current state.
  void rebuild_preconditioner();
  // The global vector of a local one as a flat host array (checkpoints).
  std::vector<double> global_values(const ConstVector& local) const;

  FluidMesh mesh_;                                   // the whole mesh
  std::unique_ptr<SingleRankExchange> one_rank_;     // the exchange on one rank, or null
  const FluidExchange* exchange_;                    // one_rank_ or the caller's
  int num_global_unknowns_;
  FluidOperator operator_;                 // on the rank's part of the mesh
  FluidScales scales_;
  SolverConfig settings_;
  bool stokes_;
  FluidBoundaryConditions boundary_;
  Vector state_, previous_state_, older_state_, history_, body_force_, correction_;
  double density_;                 // ρ [pN·s²/μm⁴]
  Vector immersed_load_;           // b of the call's immersed forces (scaled; scratch)
  Vector stiffness_action_, stiffness_stabilization_;  // Ŝ x and P(Ŝ x) (scratch)
  Vector stiffness_carrier_;                           // x + u' (scratch)
  Vector residual_;  // also scratch for boundary_forces() (const)
  Vector zero_state_residual_;  // a Stokes step's R(0) = −b (allocated in the Stokes limit)
  Vector state_gradient_;  // G(U) during a Krylov solve
  std::unique_ptr<FluidPreconditioner> preconditioner_;  // on the owned unknowns
  // Across ranks: scratch for the Jacobian's lift of owned vectors to local ones, and for
  // Ŝ's global vectors.
  Vector lifted_direction_, lifted_action_, global_carrier_, global_action_;
  Gmres gmres_;
  bool preconditioner_current_ = false;  // Stokes: J is constant while dt is
  double last_mass_coefficient_ = -1.0;
  double time_ = 0.0;
  int steps_ = 0;

  // A Stokes step's starting guess (fluid_starting_guess.cpp): U₀ = Σ c_i U_i over the last
  // k = settings_.starting_guess_solutions solutions U_i, the c_i minimizing ‖R(U₀)‖.
  void project_starting_guess(const ImmersedTerms& immersed);
  // Keeps the converged state_ among the last solutions (the oldest goes).
  void remember_solution();
  void allocate_past_solutions();  // once, for a Stokes run that keeps solutions
  Kokkos::View<double**, Kokkos::LayoutLeft> past_solutions_;  // (unknown, k): a ring of U_i
  int past_count_ = 0;     // solutions held
  int past_newest_ = -1;   // the ring's column of the newest
  // Scratch: the combinations of the U_i whose images A U_i are orthonormal, and those images.
  Kokkos::View<double**, Kokkos::LayoutLeft> guess_states_, guess_images_;
};

}  // namespace rouleau
