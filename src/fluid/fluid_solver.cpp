// The fluid solver's construction and its solves: Newton–Raphson on the scaled residual,
// each step's J δ = −R solved by right-preconditioned GMRES with J applied element by
// element, and the time stepping around it (fluid/fluid_solver.hpp).
#include "fluid/fluid_solver.hpp"

#include <spdlog/spdlog.h>

#include <KokkosBlas1_axpby.hpp>
#include <KokkosBlas1_update.hpp>
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <utility>

#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;

// J(U)·x through the element kernels (Navier–Stokes), or A·x (Stokes: affine residual),
// plus the immersed stiffness Ŝ x when the coupling is semi-implicit.
// The state's projected gradient is computed once: U is fixed during the Krylov solve.
// Across ranks x and y are the owned entries: x is lifted to a local vector (its copies
// filled from their owners while the operator sums its interior elements), the rank's operator applied (its sums completed across
// ranks), and y is the owned part of the result.
class FluidJacobian final : public LinearOperator {
 public:
  using AddStiffness = std::function<void(const ConstVector&, const Vector&)>;
  struct Lift {
    const FluidExchange* exchange = nullptr;  // null: the owned unknowns are all the local ones
    Vector direction, action;                 // local scratch
  };
  FluidJacobian(const FluidOperator& op, const ConstVector& state, const Vector& state_gradient, bool linear,
                AddStiffness add_stiffness, Lift lift)
      : op_(op), state_(state), state_gradient_(state_gradient), linear_(linear), add_stiffness_(std::move(add_stiffness)),
        lift_(std::move(lift)) {
    if (!linear_ && op_.coefficients().viscous_reconstruction) op_.project_gradient(state_, state_gradient_);
  }
  void apply(const ConstVector& x, const Vector& y) const override {
    if (!lift_.exchange) {
      apply_local(x, y);
      return;
    }
    const auto owned = std::make_pair(0, static_cast<int>(x.extent(0)));
    Kokkos::deep_copy(Kokkos::subview(lift_.direction, owned), x);
    op_.start_filling_copies(lift_.direction);  // completed inside the operator's first element loop
    apply_local(lift_.direction, lift_.action);
    Kokkos::deep_copy(y, Kokkos::subview(lift_.action, owned));
  }

 private:
  void apply_local(const ConstVector& x, const Vector& y) const {
    if (linear_)
      op_.linear_action(x, y);
    else
      op_.jacobian_action(state_, state_gradient_, x, y);
    if (add_stiffness_) add_stiffness_(x, y);
  }
  const FluidOperator& op_;
  ConstVector state_;
  Vector state_gradient_;
  bool linear_;
  AddStiffness add_stiffness_;
  Lift lift_;
};

// ‖R‖ over the velocity rows and over the pressure rows of the first `owned` entries,
// summed over the ranks (a free function: CUDA forbids extended lambdas in private member
// functions).
void block_norms(const ConstVector& r, const int owned, const FluidExchange& exchange, double& momentum,
                 double& continuity) {
  double sums[2] = {0.0, 0.0};
  Kokkos::parallel_reduce(
      "rouleau::FluidSolver::block_norms", Kokkos::RangePolicy<ExecSpace>(0, owned),
      KOKKOS_LAMBDA(const int i, double& sm, double& sc) {
        const double v = r(i) * r(i);
        if (i % 4 == 3)
          sc += v;
        else
          sm += v;
      },
      sums[0], sums[1]);
  exchange.sum(sums, 2);
  momentum = std::sqrt(sums[0]);
  continuity = std::sqrt(sums[1]);
}

// The boundary conditions of the whole mesh on a rank's part: the constrained unknowns it
// holds (owned or copies), in its local numbering, and its local entries of the load.
FluidBoundaryConditions localize_boundary_conditions(const FluidBoundaryConditions& global,
                                                     const FluidExchange& exchange) {
  FluidBoundaryConditions local;
  local.pressure_pinned = global.pressure_pinned;
  std::vector<std::pair<int, double>> constrained;
  for (std::size_t k = 0; k < global.dirichlet_dofs.size(); ++k) {
    const int node = exchange.local_node(global.dirichlet_dofs[k] / fluid_unknowns_per_node);
    if (node >= 0)
      constrained.emplace_back(fluid_unknowns_per_node * node + global.dirichlet_dofs[k] % fluid_unknowns_per_node,
                               global.dirichlet_values[k]);
  }
  std::sort(constrained.begin(), constrained.end());
  for (const auto& [dof, value] : constrained) {
    local.dirichlet_dofs.push_back(dof);
    local.dirichlet_values.push_back(value);
  }
  local.traction_load = Vector("rouleau::FluidSolver::traction_load", exchange.local_mesh().num_unknowns());
  exchange.localize(global.traction_load, local.traction_load);
  return local;
}

// The constrained unknowns among the first `owned` (the preconditioners across ranks).
std::vector<int> owned_dirichlet(const std::vector<int>& dofs, const int owned) {
  std::vector<int> kept;
  for (int dof : dofs)
    if (dof < owned) kept.push_back(dof);
  return kept;
}

GmresSettings gmres_settings(const SolverConfig& s) {
  GmresSettings g;
  g.restart = s.gmres_restart;
  g.relative_tolerance = s.gmres_rtol;
  g.max_iterations = s.gmres_max_iterations;
  return g;
}

// J δ = −R, solved to the Eisenstat–Walker forcing term η_k (choice 2, γ = 0.9, α = 2):
// η_k = γ (‖R_k‖/‖R_{k−1}‖)², safeguarded by γ η_{k−1}² when that exceeds 0.1, capped at
// 0.1, and no tighter than needed to reach the Newton target. `iteration`: k;
// `previous_forcing`: η_{k−1} in, η_k out.
double newton_forcing(const int iteration, const double residual_norm, const double previous_norm, const double target,
                      const double gmres_rtol, double& previous_forcing) {
  double forcing = iteration == 0 ? 0.1 : 0.9 * (residual_norm / previous_norm) * (residual_norm / previous_norm);
  const double safeguard = 0.9 * previous_forcing * previous_forcing;
  if (iteration > 0 && safeguard > 0.1) forcing = std::fmax(forcing, safeguard);
  forcing = std::fmin(forcing, 0.1);
  forcing = std::fmax(forcing, std::fmax(gmres_rtol, 0.5 * target / residual_norm));
  previous_forcing = forcing;
  return forcing;
}
}  // namespace

FluidSolver::FluidSolver(const FluidMesh& mesh, const FluidConfig& fluid,
                         const std::vector<FluidBoundary>& boundaries, const SolverConfig& settings,
                         const FluidScales& scales, bool stokes, const FluidExchange* exchange)
    : mesh_(mesh),
      one_rank_(exchange ? nullptr : std::make_unique<SingleRankExchange>(mesh_)),
      exchange_(exchange ? exchange : one_rank_.get()),
      num_global_unknowns_(mesh.num_unknowns()),
      operator_(exchange_->local_mesh(), scales.length),
      scales_(scales),
      settings_(settings),
      stokes_(stokes),
      density_(fluid.density),
      boundary_(exchange_->spans_ranks()
                    ? localize_boundary_conditions(build_boundary_conditions(mesh, boundaries, scales), *exchange_)
                    : build_boundary_conditions(mesh, boundaries, scales)),
      gmres_(exchange_->num_owned_unknowns(), gmres_settings(settings), exchange_->ranks()) {
  const FluidMesh& local_mesh = operator_.mesh();
  const int n = local_mesh.num_unknowns();
  state_ = Vector("rouleau::FluidSolver::state", n);
  previous_state_ = Vector("rouleau::FluidSolver::previous_state", n);
  older_state_ = Vector("rouleau::FluidSolver::older_state", n);
  history_ = Vector("rouleau::FluidSolver::history", n);
  body_force_ = Vector("rouleau::FluidSolver::body_force", n);
  residual_ = Vector("rouleau::FluidSolver::residual", n);
  if (stokes_) zero_state_residual_ = Vector("rouleau::FluidSolver::zero_state_residual", n);
  correction_ = Vector("rouleau::FluidSolver::correction", n);
  state_gradient_ = Vector("rouleau::FluidSolver::state_gradient", 9 * local_mesh.num_dof_nodes);
  if (exchange_->element_sums()) operator_.set_node_sums(exchange_->element_sums());
  operator_.set_dirichlet(boundary_.dirichlet_dofs, boundary_.dirichlet_values);
  operator_.set_nodal_load(boundary_.traction_load);
  if (exchange_->spans_ranks()) {
    lifted_direction_ = Vector("rouleau::FluidSolver::lifted_direction", n);
    lifted_action_ = Vector("rouleau::FluidSolver::lifted_action", n);
  }
  preconditioner_ = exchange_->make_preconditioner(
      settings_, owned_dirichlet(boundary_.dirichlet_dofs, exchange_->num_owned_unknowns()));
  operator_.impose_dirichlet(state_);
  set_uniform_body_force(fluid.body_force);
}

void FluidSolver::rebuild_preconditioner() {
  ProfilingRegion region("rouleau::FluidSolver::preconditioner");
  preconditioner_->factor(operator_, state_);
}

FluidSolveReport FluidSolver::solve(const ConstVector& history, const ImmersedTerms& immersed) {
  ProfilingRegion region("rouleau::FluidSolver::solve");
  FluidSolveReport report;
  load_immersed_forces(immersed);
  if (immersed.stiffness) allocate_stiffness_scratch(immersed);
  const bool linear = stokes_;
  operator_.set_sources(history, body_force_);
  operator_.impose_dirichlet(state_);
  // An affine (Stokes) residual R(U) = A U − b is solved to ‖R‖ ≤ gmres_rtol ‖b‖, with
  // ‖b‖ = ‖R(0)‖: relative to the right-hand side, not to the residual of the starting
  // guess, so that a good start (the last step's solution, extrapolated) saves iterations.
  double rhs_norm = 0.0;
  if (linear) {
    Kokkos::deep_copy(correction_, 0.0);
    operator_.residual(correction_, correction_, residual_);
    Kokkos::deep_copy(zero_state_residual_, residual_);
    rhs_norm = exchange_->norm(residual_);
    project_starting_guess(immersed);
  }
  residual_at_state(immersed, true, linear);
  double residual_norm = exchange_->norm(residual_);
  report.initial_residual = residual_norm;
  const double target = linear ? std::fmax(settings_.newton_atol, settings_.gmres_rtol * rhs_norm)
                               : std::fmax(settings_.newton_atol, settings_.newton_rtol * residual_norm);
  if (!std::isfinite(residual_norm)) report.failure = "the residual is not finite";
  double previous_norm = residual_norm, previous_forcing = 0.1;
  while (report.failure.empty() && residual_norm > target && !report.stalled_at_round_off &&
         report.newton_iterations < settings_.newton_max_iterations) {
    // Preconditioner from the Jacobian at the current state (constant in the Stokes limit).
    if (!linear || !preconditioner_current_) {
      rebuild_preconditioner();
      preconditioner_current_ = true;
    }
    // An affine (Stokes) residual is solved once, down to its target (gmres_rtol ‖b‖); a
    // nonlinear one to the Eisenstat–Walker forcing term.
    const double forcing = linear ? std::fmin(0.5, target / residual_norm)
                                  : newton_forcing(report.newton_iterations, residual_norm, previous_norm, target,
                                                   settings_.gmres_rtol, previous_forcing);
    previous_norm = residual_norm;
    const GmresResult g = newton_step(immersed, linear, forcing);
    report.gmres_iterations += g.iterations;
    ++report.newton_iterations;
    residual_norm = exchange_->norm(residual_);
    // ‖δ‖ ≤ newton_step_rtol ‖U‖: the update no longer changes the state, so the residual
    // is at its round-off floor (converged, even if above the residual target).
    if (!linear && settings_.newton_step_rtol > 0.0 &&
        exchange_->norm(correction_) <= settings_.newton_step_rtol * exchange_->norm(state_))
      report.stalled_at_round_off = true;
    if (spdlog::should_log(spdlog::level::debug)) log_newton_step(report, g, forcing, residual_norm, target);
    if (!std::isfinite(residual_norm)) {
      report.failure = "the residual is not finite after Newton step " + std::to_string(report.newton_iterations);
      break;
    }
    if (!g.converged && residual_norm > target) {
      std::ostringstream msg;
      msg << "GMRES did not converge in " << g.iterations << " iterations (linear residual " << g.final_residual
          << " from " << g.initial_residual << ")";
      report.failure = msg.str();
      break;
    }
    if (linear) break;  // affine residual: one Krylov solve is the solution
  }
  block_norms(residual_, exchange_->num_owned_unknowns(), *exchange_, report.momentum_residual,
              report.continuity_residual);
  report.converged = report.failure.empty() && (residual_norm <= target || linear || report.stalled_at_round_off);
  if (report.failure.empty() && !report.converged) {
    std::ostringstream msg;
    msg << "Newton did not converge in " << report.newton_iterations << " iterations (residual " << residual_norm
        << ", target " << target << ")";
    report.failure = msg.str();
  }
  return report;
}

GmresResult FluidSolver::newton_step(const ImmersedTerms& immersed, const bool linear, const double forcing) {
  const Preconditioner& M = *preconditioner_;
  KokkosBlas::axpby(-1.0, residual_, 0.0, residual_);
  Kokkos::deep_copy(correction_, 0.0);
  FluidJacobian::AddStiffness add_stiffness;
  if (immersed.stiffness)
    add_stiffness = [this, &immersed](const ConstVector& x, const Vector& y) {
      add_immersed_stiffness(immersed, x, y, true, StiffnessArgument::direction);
    };
  FluidJacobian J(operator_, state_, state_gradient_, linear, add_stiffness,
                  {exchange_->spans_ranks() ? exchange_ : nullptr, lifted_direction_, lifted_action_});
  // GMRES on the owned unknowns (all of them on one rank); the copies follow.
  const auto owned = std::make_pair(0, exchange_->num_owned_unknowns());
  const GmresResult g =
      gmres_.solve(J, M, Kokkos::subview(residual_, owned), Kokkos::subview(correction_, owned), forcing);
  exchange_->update_copies(correction_);
  KokkosBlas::axpby(1.0, correction_, 1.0, state_);
  residual_at_state(immersed, true, linear);
  return g;
}

void FluidSolver::residual_at_state(const ImmersedTerms& immersed, const bool constrained_rows, const bool affine) {
  if (affine && constrained_rows && !exchange_->spans_ranks()) {
    // R(U) = A U + R(0): the linear action (the uniform boxes' stencil) instead of a pass
    // over the elements with the sources; equal to round-off on one rank. Across ranks the
    // element pass stays: a run split over one and two ranks moved 3× further from the
    // one-rank run with it (1.3e-7 of the state after 8 steps, against 3.9e-8), not yet
    // understood.
    operator_.linear_action(state_, residual_);
    KokkosBlas::axpy(1.0, zero_state_residual_, residual_);
  } else {
    operator_.residual(state_, state_, residual_, constrained_rows);
  }
  add_immersed_stiffness(immersed, state_, residual_, constrained_rows, StiffnessArgument::state);
}

void FluidSolver::log_newton_step(const FluidSolveReport& report, const GmresResult& g, const double forcing,
                                  const double residual_norm, const double target) const {
  double momentum = 0.0, continuity = 0.0;
  block_norms(residual_, exchange_->num_owned_unknowns(), *exchange_, momentum, continuity);
  spdlog::debug("Newton {}: GMRES {} iterations to {:.1e} ({}), residual {:.3e} (momentum {:.3e}, continuity "
                "{:.3e}), target {:.3e}",
                report.newton_iterations, g.iterations, forcing, g.converged ? "converged" : "not converged",
                residual_norm, momentum, continuity, target);
}

void FluidSolver::set_time_coefficients(double mass_coefficient, double inverse_dt) {
  FluidCoefficients c;
  c.reynolds = scales_.reynolds;
  c.convection = stokes_ ? 0 : 1;
  c.viscous_reconstruction = 1;
  c.mass_coefficient = mass_coefficient;
  c.inverse_dt = inverse_dt;
  // The Stokes operator, and so its preconditioner, changes only with the time step.
  if (c.mass_coefficient != last_mass_coefficient_) preconditioner_current_ = false;
  last_mass_coefficient_ = c.mass_coefficient;
  operator_.set_coefficients(c);
}

FluidSolveReport FluidSolver::solve_steady(const ImmersedTerms& immersed) {
  set_time_coefficients(0.0, 0.0);
  return solve(ConstVector(), immersed);
}

FluidSolveReport FluidSolver::advance(double dt, TimeScheme scheme, const ImmersedTerms& immersed) {
  // BDF: u_t ≈ (α0 u^{n+1} + α1 u^n + α2 u^{n−1}) / Δt, in scaled time Δt̂ = Δt U/L.
  const double dt_scaled = dt * scales_.velocity / scales_.length;
  const bool bdf2 = scheme == TimeScheme::bdf2 && steps_ > 0;
  const double a0 = bdf2 ? 1.5 : 1.0, a1 = bdf2 ? -2.0 : -1.0, a2 = bdf2 ? 0.5 : 0.0;
  set_time_coefficients(a0 / dt_scaled, 1.0 / dt_scaled);

  // H = (α1 u^n + α2 u^{n−1}) / Δt̂
  Kokkos::deep_copy(older_state_, bdf2 ? previous_state_ : state_);
  Kokkos::deep_copy(previous_state_, state_);
  KokkosBlas::update(a1 / dt_scaled, previous_state_, a2 / dt_scaled, older_state_, 0.0, history_);
  // The starting guess: U^n extrapolated linearly in time, 2 U^n − U^{n−1} (U^n on the first
  // step), which a Stokes step replaces by a better one once it knows two solutions
  // (project_starting_guess). It only shortens the solve: the solution does not depend on it.
  if (steps_ > 0 && bdf2) KokkosBlas::axpby(-1.0, older_state_, 2.0, state_);
  FluidSolveReport report = solve(history_, immersed);
  if (report.converged) {
    time_ += dt;
    ++steps_;
    remember_solution();
  }
  return report;
}

}  // namespace rouleau
