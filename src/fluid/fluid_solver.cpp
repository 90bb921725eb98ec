#include "fluid/fluid_solver.hpp"

#include <spdlog/spdlog.h>

#include <KokkosBlas1_axpby.hpp>
#include <KokkosBlas1_nrm2.hpp>
#include <KokkosBlas1_update.hpp>
#include <cmath>
#include <sstream>

#include "fluid/fluid_element_types.hpp"
#include "run/profiling_region.hpp"
#include "util/view_transfer.hpp"

#include <algorithm>
#include <functional>
#include <utility>

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;

// J(U)·x through the element kernels (Navier–Stokes), or A·x (Stokes: affine residual),
// plus the immersed stiffness Ŝ x when the coupling is semi-implicit.
// The state's projected gradient is computed once: U is fixed during the Krylov solve.
class FluidJacobian final : public LinearOperator {
 public:
  using AddStiffness = std::function<void(const ConstVector&, const Vector&)>;
  FluidJacobian(const FluidOperator& op, const ConstVector& state, const Vector& state_gradient, bool linear,
                AddStiffness add_stiffness)
      : op_(op), state_(state), state_gradient_(state_gradient), linear_(linear), add_stiffness_(std::move(add_stiffness)) {
    if (!linear_ && op_.coefficients().viscous_reconstruction) op_.project_gradient(state_, state_gradient_);
  }
  void apply(const ConstVector& x, const Vector& y) const override {
    if (linear_)
      op_.linear_action(x, y);
    else
      op_.jacobian_action(state_, state_gradient_, x, y);
    if (add_stiffness_) add_stiffness_(x, y);
  }

 private:
  const FluidOperator& op_;
  ConstVector state_;
  Vector state_gradient_;
  bool linear_;
  AddStiffness add_stiffness_;
};

// ‖R‖ over the velocity rows and over the pressure rows (a free function: CUDA forbids
// extended lambdas in private member functions).
void block_norms(const ConstVector& r, double& momentum, double& continuity) {
  double m = 0.0, c = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::FluidSolver::block_norms", Kokkos::RangePolicy<ExecSpace>(0, r.extent(0)),
      KOKKOS_LAMBDA(const int i, double& sm, double& sc) {
        const double v = r(i) * r(i);
        if (i % 4 == 3)
          sc += v;
        else
          sm += v;
      },
      m, c);
  momentum = std::sqrt(m);
  continuity = std::sqrt(c);
}

// v(rows(i)) = 0 (a free function: CUDA forbids extended lambdas in private member
// functions).
void zero_rows(const Kokkos::View<int*>& rows, const Vector& v) {
  Kokkos::parallel_for(
      "rouleau::FluidSolver::zero_rows", Kokkos::RangePolicy<ExecSpace>(0, rows.extent(0)),
      KOKKOS_LAMBDA(const int i) { v(rows(i)) = 0.0; });
}

GmresSettings gmres_settings(const SolverConfig& s) {
  GmresSettings g;
  g.restart = s.gmres_restart;
  g.relative_tolerance = s.gmres_rtol;
  g.max_iterations = s.gmres_max_iterations;
  return g;
}
}  // namespace

FluidSolver::FluidSolver(const FluidMesh& mesh, const FluidConfig& fluid,
                         const std::vector<FluidBoundary>& boundaries, const SolverConfig& settings,
                         const FluidScales& scales, bool stokes)
    : operator_(mesh, scales.length),
      scales_(scales),
      settings_(settings),
      stokes_(stokes),
      density_(fluid.density),
      boundary_(build_boundary_conditions(mesh, boundaries, scales)),
      block_jacobi_(mesh.num_dof_nodes),
      gmres_(mesh.num_unknowns(), gmres_settings(settings)) {
  const int n = mesh.num_unknowns();
  state_ = Vector("rouleau::FluidSolver::state", n);
  previous_state_ = Vector("rouleau::FluidSolver::previous_state", n);
  older_state_ = Vector("rouleau::FluidSolver::older_state", n);
  history_ = Vector("rouleau::FluidSolver::history", n);
  body_force_ = Vector("rouleau::FluidSolver::body_force", n);
  residual_ = Vector("rouleau::FluidSolver::residual", n);
  correction_ = Vector("rouleau::FluidSolver::correction", n);
  blocks_ = Vector("rouleau::FluidSolver::blocks", 16 * mesh.num_dof_nodes);
  state_gradient_ = Vector("rouleau::FluidSolver::state_gradient", 9 * mesh.num_dof_nodes);
  operator_.set_dirichlet(boundary_.dirichlet_dofs, boundary_.dirichlet_values);
  operator_.set_nodal_load(boundary_.traction_load);
  if (settings_.preconditioner == PreconditionerType::ilu0 || settings_.preconditioner == PreconditionerType::multigrid) {
    matrix_graph_ = build_fluid_matrix_graph(mesh);
    matrix_values_ = Vector("rouleau::FluidSolver::matrix_values", matrix_graph_.entries.extent(0));
  }
  if (settings_.preconditioner == PreconditionerType::ilu0)
    ilu0_ = std::make_unique<Ilu0Preconditioner>(matrix_graph_.row_map, matrix_graph_.entries);
  if (settings_.preconditioner == PreconditionerType::multigrid)
    multigrid_ = std::make_unique<AggregationMultigrid>(matrix_graph_, fluid_node_strength(mesh));
  operator_.impose_dirichlet(state_);
  set_uniform_body_force(fluid.body_force);
}

void FluidSolver::set_body_force(const std::vector<double>& force_density) {
  const int nodes = operator_.mesh().num_dof_nodes;
  auto host = Kokkos::create_mirror_view(body_force_);
  Kokkos::deep_copy(host, 0.0);
  const double scale = 1.0 / scales_.body_force();
  for (int i = 0; i < nodes; ++i)
    for (int d = 0; d < 3; ++d) host(4 * i + d) = force_density[3 * i + d] * scale;
  Kokkos::deep_copy(body_force_, host);
}

void FluidSolver::set_uniform_body_force(const std::array<double, 3>& force_density) {
  std::vector<double> field(3 * operator_.mesh().num_dof_nodes);
  for (size_t i = 0; i < field.size(); ++i) field[i] = force_density[i % 3];
  set_body_force(field);
}

void FluidSolver::set_velocity(
    const std::function<std::array<double, 3>(const std::array<double, 3>&)>& velocity) {
  const FluidMesh& mesh = operator_.mesh();
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto state = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), state_);
  for (int n = 0; n < mesh.num_nodes; ++n) {
    const auto v = velocity({coordinates(n, 0), coordinates(n, 1), coordinates(n, 2)});
    for (int c = 0; c < 3; ++c) state(4 * mesh.dof_node_of_node[n] + c) = v[c] / scales_.velocity;
  }
  Kokkos::deep_copy(state_, state);
  operator_.impose_dirichlet(state_);
}

void FluidSolver::prescribe_boundary_velocity(
    const std::function<std::array<double, 3>(const std::array<double, 3>&)>& velocity) {
  const FluidMesh& mesh = operator_.mesh();
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  std::vector<int> node_of_dof_node(mesh.num_dof_nodes, -1);
  for (int n = 0; n < mesh.num_nodes; ++n)
    if (node_of_dof_node[mesh.dof_node_of_node[n]] < 0) node_of_dof_node[mesh.dof_node_of_node[n]] = n;
  for (size_t k = 0; k < boundary_.dirichlet_dofs.size(); ++k) {
    const int dof = boundary_.dirichlet_dofs[k], component = dof % 4;
    if (component == 3) continue;
    const int node = node_of_dof_node[dof / 4];
    const auto v = velocity({coordinates(node, 0), coordinates(node, 1), coordinates(node, 2)});
    boundary_.dirichlet_values[k] = v[component] / scales_.velocity;
  }
  operator_.set_dirichlet(boundary_.dirichlet_dofs, boundary_.dirichlet_values);
  operator_.impose_dirichlet(state_);
}

std::vector<std::array<double, 3>> FluidSolver::boundary_forces(const std::vector<std::string>& sides) const {
  const FluidMesh& mesh = operator_.mesh();
  // One residual without constraint rows and one host copy for all the sides asked.
  operator_.residual(state_, state_, residual_, false);
  add_immersed_stiffness(state_, residual_, false, StiffnessArgument::state);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), residual_);
  std::vector<std::array<double, 3>> forces;
  for (const std::string& side : sides) {
    std::vector<int> dof_nodes;
    for (int node : mesh.boundary(side).nodes) dof_nodes.push_back(mesh.dof_node_of_node[node]);
    std::sort(dof_nodes.begin(), dof_nodes.end());
    dof_nodes.erase(std::unique(dof_nodes.begin(), dof_nodes.end()), dof_nodes.end());
    // R_a = ∫ ∇N_a : σ − ... = the force the wall exerts on the fluid at node a; the fluid
    // pushes back with −R_a. Scaled force → pN: × P L².
    std::array<double, 3> force{0.0, 0.0, 0.0};
    for (int n : dof_nodes)
      for (int d = 0; d < 3; ++d) force[d] -= r(4 * n + d) * scales_.force();
    forces.push_back(force);
  }
  return forces;
}

namespace {
// ∫ 1, ∫ u_x, ∫ u_y, ∫ u_z, ∫ |u|² over the mesh (scaled), by the element's quadrature
// with u(ξ_q) = Σ_a N_a(ξ_q) u_a.
template <class Element>
std::array<double, 5> integrate_velocity(const FluidOperator& op, const ConstVector& state) {
  const auto geometry = op.geometry();
  const auto dof_nodes = op.mesh().element_dof_nodes;
  double v = 0.0, ux = 0.0, uy = 0.0, uz = 0.0, uu = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::FluidSolver::velocity_integrals", Kokkos::RangePolicy<ExecSpace>(0, op.mesh().num_elements),
      KOKKOS_LAMBDA(const int e, double& volume, double& mx, double& my, double& mz, double& squared) {
        for (int q = 0; q < Element::quadrature_points; ++q) {
          double xi[3];
          Element::quadrature_point(q, xi);
          const double dv = geometry(e, q, 9);
          double u[3] = {0.0, 0.0, 0.0};
          for (int a = 0; a < Element::nodes; ++a) {
            const double N = Element::shape(a, xi);
            const int n = dof_nodes(e, a);
            for (int c = 0; c < 3; ++c) u[c] += N * state(4 * n + c);
          }
          volume += dv;
          mx += dv * u[0];
          my += dv * u[1];
          mz += dv * u[2];
          squared += dv * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        }
      },
      v, ux, uy, uz, uu);
  return {v, ux, uy, uz, uu};
}
}  // namespace

std::array<double, 5> FluidSolver::velocity_integrals() const {
  return visit_fluid_element(operator_.mesh().element_type, [&](auto element) {
    return integrate_velocity<decltype(element)>(operator_, state_);
  });
}

std::array<double, 3> FluidSolver::mean_velocity() const {
  const auto integrals = velocity_integrals();
  const double U = scales_.velocity;
  return {integrals[1] / integrals[0] * U, integrals[2] / integrals[0] * U, integrals[3] / integrals[0] * U};
}

double FluidSolver::kinetic_energy() const {
  // ½ ρ ∫ |u|² dV, the integral in scaled (x/L, u/U) variables: × U² L³
  const double U = scales_.velocity, L = scales_.length;
  return 0.5 * density_ * velocity_integrals()[4] * U * U * L * L * L;
}

void FluidSolver::set_immersed_forces(const ConstVector& nodal_forces) {
  if (immersed_load_.extent(0) == 0) {
    immersed_load_ = Vector("rouleau::FluidSolver::immersed_load", state_.extent(0));
    operator_.set_immersed_load(immersed_load_);
  }
  // b = F / (P L²), the forces in the residual's scale
  const auto load = immersed_load_;
  const double inverse_force_scale = 1.0 / scales_.force();
  Kokkos::parallel_for(
      "rouleau::FluidSolver::set_immersed_forces", Kokkos::RangePolicy<ExecSpace>(0, load.extent(0)),
      KOKKOS_LAMBDA(const int i) { load(i) = inverse_force_scale * nodal_forces(i); });
}

void FluidSolver::total_velocity(const Vector& out) const {
  operator_.subscale_velocity(state_, out);
  KokkosBlas::axpy(1.0, state_, out);
}

void FluidSolver::set_immersed_forces_in_stabilization(bool in_stabilization) {
  operator_.set_immersed_load_in_stabilization(in_stabilization);
}

void FluidSolver::set_immersed_stiffness(const LinearOperator* stiffness, bool moves_with_subscale) {
  immersed_stiffness_ = stiffness;
  stiffness_moves_with_subscale_ = moves_with_subscale;
  if (stiffness && stiffness_action_.extent(0) == 0) {
    stiffness_action_ = Vector("rouleau::FluidSolver::stiffness_action", state_.extent(0));
    stiffness_stabilization_ = Vector("rouleau::FluidSolver::stiffness_stabilization", state_.extent(0));
  }
  if (stiffness && moves_with_subscale && stiffness_carrier_.extent(0) == 0)
    stiffness_carrier_ = Vector("rouleau::FluidSolver::stiffness_carrier", state_.extent(0));
}

void FluidSolver::add_immersed_stiffness(const ConstVector& x, const Vector& y, bool skip_constrained,
                                         StiffnessArgument argument) const {
  if (!immersed_stiffness_) return;
  ConstVector carrier = x;
  if (stiffness_moves_with_subscale_) {
    // c = x + u'(x) for the state, x + u'_x (τ frozen at the state) for a direction.
    if (argument == StiffnessArgument::state)
      operator_.subscale_velocity(x, stiffness_carrier_);
    else
      operator_.subscale_velocity_action(state_, x, stiffness_carrier_);
    KokkosBlas::axpy(1.0, x, stiffness_carrier_);
    carrier = stiffness_carrier_;
  }
  immersed_stiffness_->apply(carrier, stiffness_action_);
  // Ŝx is minus the change of the immersed loads; that change enters the stabilization's
  // strong residual as the loads do: Ŝx − P(Ŝx), P = FluidOperator::load_stabilization.
  if (operator_.immersed_load_in_stabilization()) {
    operator_.load_stabilization(state_, stiffness_action_, stiffness_stabilization_);
    KokkosBlas::axpy(-1.0, stiffness_stabilization_, stiffness_action_);
  }
  if (skip_constrained) zero_rows(operator_.dirichlet_dofs(), stiffness_action_);
  KokkosBlas::axpy(1.0, stiffness_action_, y);
}

void FluidSolver::rebuild_preconditioner() {
  ProfilingRegion region("rouleau::FluidSolver::preconditioner");
  switch (settings_.preconditioner) {
    case PreconditionerType::block_jacobi:
      operator_.diagonal_blocks(state_, blocks_);
      block_jacobi_.factor(blocks_);
      break;
    case PreconditionerType::ilu0:
      operator_.assemble_jacobian(state_, matrix_graph_, matrix_values_);
      ilu0_->factor(matrix_values_);
      break;
    case PreconditionerType::multigrid:
      operator_.assemble_jacobian(state_, matrix_graph_, matrix_values_);
      multigrid_->set_values(matrix_values_);
      break;
    case PreconditionerType::none:
      break;
  }
}

const Preconditioner& FluidSolver::preconditioner() const {
  switch (settings_.preconditioner) {
    case PreconditionerType::block_jacobi: return block_jacobi_;
    case PreconditionerType::ilu0: return *ilu0_;
    case PreconditionerType::multigrid: return *multigrid_;
    case PreconditionerType::none: break;
  }
  return identity_;
}

FluidSolveReport FluidSolver::solve(const ConstVector& history) {
  ProfilingRegion region("rouleau::FluidSolver::solve");
  FluidSolveReport report;
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
    rhs_norm = KokkosBlas::nrm2(residual_);
  }
  operator_.residual(state_, state_, residual_);
  add_immersed_stiffness(state_, residual_, true, StiffnessArgument::state);
  double norm = KokkosBlas::nrm2(residual_);
  report.initial_residual = norm;
  const double target = linear ? std::fmax(settings_.newton_atol, settings_.gmres_rtol * rhs_norm)
                               : std::fmax(settings_.newton_atol, settings_.newton_rtol * norm);
  if (!std::isfinite(norm)) report.failure = "the residual is not finite";
  double previous_norm = norm, previous_forcing = 0.1;
  while (report.failure.empty() && norm > target && !report.stalled_at_round_off &&
         report.newton_iterations < settings_.newton_max_iterations) {
    // Preconditioner from the Jacobian at the current state (constant in the Stokes limit).
    if (!linear || !preconditioner_current_) {
      rebuild_preconditioner();
      preconditioner_current_ = true;
    }
    const Preconditioner& M = preconditioner();
    // J δ = −R, solved to the Eisenstat–Walker forcing term η_k (choice 2, γ = 0.9, α = 2):
    // η_k = γ (‖R_k‖/‖R_{k−1}‖)², safeguarded by γ η_{k−1}² when that exceeds 0.1, capped at
    // 0.1, and no tighter than needed to reach the Newton target. An affine (Stokes)
    // residual is solved once, down to its target (gmres_rtol ‖b‖).
    double forcing = std::fmin(0.5, target / norm);
    if (!linear) {
      forcing = report.newton_iterations == 0 ? 0.1 : 0.9 * (norm / previous_norm) * (norm / previous_norm);
      const double safeguard = 0.9 * previous_forcing * previous_forcing;
      if (report.newton_iterations > 0 && safeguard > 0.1) forcing = std::fmax(forcing, safeguard);
      forcing = std::fmin(forcing, 0.1);
      forcing = std::fmax(forcing, std::fmax(settings_.gmres_rtol, 0.5 * target / norm));
      previous_forcing = forcing;
    }
    previous_norm = norm;
    KokkosBlas::axpby(-1.0, residual_, 0.0, residual_);
    Kokkos::deep_copy(correction_, 0.0);
    FluidJacobian::AddStiffness add_stiffness;
    if (immersed_stiffness_)
      add_stiffness = [this](const ConstVector& x, const Vector& y) {
        add_immersed_stiffness(x, y, true, StiffnessArgument::direction);
      };
    FluidJacobian J(operator_, state_, state_gradient_, linear, add_stiffness);
    const GmresResult g = gmres_.solve(J, M, residual_, correction_, forcing);
    report.gmres_iterations += g.iterations;
    ++report.newton_iterations;
    KokkosBlas::axpby(1.0, correction_, 1.0, state_);
    operator_.residual(state_, state_, residual_);
    add_immersed_stiffness(state_, residual_, true, StiffnessArgument::state);
    norm = KokkosBlas::nrm2(residual_);
    // ‖δ‖ ≤ newton_step_rtol ‖U‖: the update no longer changes the state, so the residual
    // is at its round-off floor (converged, even if above the residual target).
    if (!linear && settings_.newton_step_rtol > 0.0 &&
        KokkosBlas::nrm2(correction_) <= settings_.newton_step_rtol * KokkosBlas::nrm2(state_))
      report.stalled_at_round_off = true;
    if (spdlog::should_log(spdlog::level::debug)) {
      double momentum = 0.0, continuity = 0.0;
      block_norms(residual_, momentum, continuity);
      spdlog::debug("Newton {}: GMRES {} iterations to {:.1e} ({}), residual {:.3e} (momentum {:.3e}, continuity "
                    "{:.3e}), target {:.3e}",
                    report.newton_iterations, g.iterations, forcing, g.converged ? "converged" : "not converged",
                    norm, momentum, continuity, target);
    }
    if (!std::isfinite(norm)) {
      report.failure = "the residual is not finite after Newton step " + std::to_string(report.newton_iterations);
      break;
    }
    if (!g.converged && norm > target) {
      std::ostringstream msg;
      msg << "GMRES did not converge in " << g.iterations << " iterations (linear residual " << g.final_residual
          << " from " << g.initial_residual << ")";
      report.failure = msg.str();
      break;
    }
    if (linear) break;  // affine residual: one Krylov solve is the solution
  }
  block_norms(residual_, report.momentum_residual, report.continuity_residual);
  report.converged = report.failure.empty() && (norm <= target || linear || report.stalled_at_round_off);
  if (report.failure.empty() && !report.converged) {
    std::ostringstream msg;
    msg << "Newton did not converge in " << report.newton_iterations << " iterations (residual " << norm
        << ", target " << target << ")";
    report.failure = msg.str();
  }
  return report;
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

FluidSolveReport FluidSolver::solve_steady() {
  set_time_coefficients(0.0, 0.0);
  return solve(ConstVector());
}

FluidSolveReport FluidSolver::advance(double dt, TimeScheme scheme) {
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
  // step). It only shortens the solve: the solution does not depend on it.
  if (steps_ > 0 && bdf2) KokkosBlas::axpby(-1.0, older_state_, 2.0, state_);
  FluidSolveReport report = solve(history_);
  if (report.converged) {
    time_ += dt;
    ++steps_;
  }
  return report;
}

void FluidSolver::save_state(CheckpointData& data) const {
  data.reals["fluid/state"] = to_flat_vector(state_);
  data.reals["fluid/previous_state"] = to_flat_vector(previous_state_);
  data.reals["fluid/time"] = {time_};
  data.integers["fluid/steps"] = {steps_};
}

void FluidSolver::restore_state(const CheckpointData& data) {
  const long long n = static_cast<long long>(state_.extent(0));
  from_flat_vector(data.real("fluid/state", n), state_, "fluid/state");
  from_flat_vector(data.real("fluid/previous_state", n), previous_state_, "fluid/previous_state");
  time_ = data.real("fluid/time", 1).front();
  steps_ = static_cast<int>(data.integer("fluid/steps", 1).front());
}

void FluidSolver::velocity_and_pressure(std::vector<double>& velocity, std::vector<double>& pressure) const {
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), state_);
  const FluidMesh& mesh = operator_.mesh();
  velocity.resize(3 * mesh.num_nodes);
  pressure.resize(mesh.num_nodes);
  for (int n = 0; n < mesh.num_nodes; ++n) {
    const int d = mesh.dof_node_of_node[n];
    for (int c = 0; c < 3; ++c) velocity[3 * n + c] = host(4 * d + c) * scales_.velocity;
    pressure[n] = host(4 * d + 3) * scales_.pressure;
  }
}

}  // namespace rouleau
