#pragma once
// What the cells add to a fluid solve (coupling/immersed_coupling.hpp), passed to each
// FluidSolver call that evaluates the residual with cells present; the solver keeps none of
// it between calls.
#include <Kokkos_Core.hpp>

#include "fluid/subscale_region.hpp"
#include "solver/linear_operator.hpp"

namespace rouleau {

struct ImmersedTerms {
  // F_J = Σ_I Φ_J(x_I) F_I, the cells' forces spread to the fluid's unknowns [pN] (paper
  // eq. 16), in the global numbering, node-interleaved like the state (velocity entries
  // read). They enter the momentum residual as nodal loads, the exact transpose of
  // interpolation. Empty: no cells.
  Kokkos::View<const double*> loads;
  // The loads also enter the stabilization's strong residual as the force density they
  // stand for (FluidOperator::load_stabilization); without it PSPG drives a flux τ ∇p
  // through the cells.
  bool loads_in_stabilization = false;
  // The semi-implicit coupling's linearized cell forces: an operator Ŝ on the scaled state
  // whose action enters the residual, R(U) = R_fluid(U) + Ŝ c(U), and so the Jacobian
  // (zero on the constrained rows; Ŝ acts on global vectors); with the loads in the
  // stabilization, also its share −P(Ŝ c). c(U) is the velocity the cells move with: U's,
  // or U + u'(U) when `stiffness_moves_with_subscale` (the Jacobian then takes
  // δ + u'_δ, τ frozen; FluidOperator::subscale_velocity_action). Null: the explicit
  // coupling. The preconditioner does not see it.
  const LinearOperator* stiffness = nullptr;
  bool stiffness_moves_with_subscale = false;
  // Where the cells read u' (their RKPM supports' two rings of elements, on one rank): the
  // subscale velocity and its derivative are computed there only. Not restricted: the
  // whole mesh.
  SubscaleRegion subscale_region;
  // Across ranks: the global dof nodes the cells read and load (their RKPM supports,
  // ascending), where the stiffness's global vectors are replicated; empty: every node.
  Kokkos::View<const int*> cell_support_nodes;
  // Across ranks, when each rank computes a share of the cells: the stiffness's action is
  // this rank's share, summed over the ranks at `cell_support_nodes`.
  bool stiffness_is_shared = false;
};

}  // namespace rouleau
