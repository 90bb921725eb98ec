// How the cells' terms of a solve (fluid/immersed_terms.hpp) enter the fluid solver: the
// spread forces as the operator's nodal load, in the residual's scale, and the
// semi-implicit coupling's stiffness Ŝ acting on the velocity the cells move with, in the
// residual and the Jacobian (fluid/fluid_solver.hpp).
#include "fluid/fluid_solver.hpp"

#include <KokkosBlas1_axpby.hpp>

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;

// v(rows(i)) = 0 (a free function: CUDA forbids extended lambdas in private member
// functions).
void zero_rows(const Kokkos::View<int*>& rows, const Vector& v) {
  Kokkos::parallel_for(
      "rouleau::FluidSolver::zero_rows", Kokkos::RangePolicy<ExecSpace>(0, rows.extent(0)),
      KOKKOS_LAMBDA(const int i) { v(rows(i)) = 0.0; });
}

// v *= factor (a free function: CUDA forbids extended lambdas in private member functions).
void scale(const Vector& v, const double factor) {
  Kokkos::parallel_for(
      "rouleau::FluidSolver::scale", Kokkos::RangePolicy<ExecSpace>(0, v.extent(0)),
      KOKKOS_LAMBDA(const int i) { v(i) *= factor; });
}
}  // namespace

void FluidSolver::load_immersed_forces(const ImmersedTerms& immersed) {
  if (immersed.loads.extent(0) == 0) {
    operator_.set_immersed_load(ConstVector());
    return;
  }
  if (immersed_load_.extent(0) == 0)
    immersed_load_ = Vector("rouleau::FluidSolver::immersed_load", state_.extent(0));
  // b = F / (P L²), the forces in the residual's scale; across ranks, at the rank's nodes.
  const auto load = immersed_load_;
  const double inverse_force_scale = 1.0 / scales_.force();
  exchange_->localize(immersed.loads, load);
  scale(load, inverse_force_scale);
  operator_.set_immersed_load(immersed_load_);
  operator_.set_immersed_load_in_stabilization(immersed.loads_in_stabilization);
}

void FluidSolver::add_immersed_stiffness(const ImmersedTerms& immersed, const ConstVector& x, const Vector& y,
                                         bool skip_constrained, StiffnessArgument argument) const {
  if (!immersed.stiffness) return;
  ConstVector carrier = x;
  if (immersed.stiffness_moves_with_subscale) {
    // c = x + u'(x) for the state, x + u'_x (τ frozen at the state) for a direction.
    if (argument == StiffnessArgument::state)
      operator_.subscale_velocity(x, stiffness_carrier_, immersed.subscale_region);
    else
      operator_.subscale_velocity_action(state_, x, stiffness_carrier_, immersed.subscale_region);
    KokkosBlas::axpy(1.0, x, stiffness_carrier_);
    carrier = stiffness_carrier_;
  }
  // Ŝ acts on the whole mesh's vectors: across ranks, on the carrier replicated from
  // every rank's owned entries, its action taken back at the rank's nodes.
  if (exchange_->spans_ranks()) {
    gather_global(carrier, global_carrier_, immersed.cell_support_nodes);
    immersed.stiffness->apply(global_carrier_, global_action_);
    if (immersed.stiffness_is_shared) exchange_->sum_at_nodes(global_action_, immersed.cell_support_nodes);
    exchange_->localize(global_action_, stiffness_action_);
  } else {
    immersed.stiffness->apply(carrier, stiffness_action_);
  }
  // Ŝx is minus the change of the immersed loads; that change enters the stabilization's
  // strong residual as the loads do: Ŝx − P(Ŝx), P = FluidOperator::load_stabilization.
  if (operator_.immersed_load_in_stabilization()) {
    operator_.load_stabilization(state_, stiffness_action_, stiffness_stabilization_);
    KokkosBlas::axpy(-1.0, stiffness_stabilization_, stiffness_action_);
  }
  if (skip_constrained) zero_rows(operator_.dirichlet_dofs(), stiffness_action_);
  KokkosBlas::axpy(1.0, stiffness_action_, y);
}

void FluidSolver::allocate_stiffness_scratch(const ImmersedTerms& immersed) {
  if (stiffness_action_.extent(0) == 0) {
    stiffness_action_ = Vector("rouleau::FluidSolver::stiffness_action", state_.extent(0));
    stiffness_stabilization_ = Vector("rouleau::FluidSolver::stiffness_stabilization", state_.extent(0));
    if (exchange_->spans_ranks()) {
      global_carrier_ = Vector("rouleau::FluidSolver::global_carrier", num_global_unknowns_);
      global_action_ = Vector("rouleau::FluidSolver::global_action", num_global_unknowns_);
    }
  }
  if (immersed.stiffness_moves_with_subscale && stiffness_carrier_.extent(0) == 0)
    stiffness_carrier_ = Vector("rouleau::FluidSolver::stiffness_carrier", state_.extent(0));
}

}  // namespace rouleau
