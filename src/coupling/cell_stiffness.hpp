#pragma once
// The cells' stiffness as the fluid sees it, for the semi-implicit coupling.
//
// The explicit step spreads the cells' forces at x^n; it is stable only while the stiffest
// force relaxes slower than a step (Δt ≲ μ h_f / G_eff). The semi-implicit step spreads
// the forces at the end of the step instead, x^{n+1} = x^n + Δt I u^{n+1}, linearized
// about x^n:
//     f(x^{n+1}) ≈ f(x^n) + K (Δt I u^{n+1}),      K = ∂f/∂x at x^n,
// so the fluid's momentum rows gain the term −S K Δt I u (S spreads, I interpolates,
// paper eqs. 15, 16). Since f = −∂E/∂x of the elastic, interaction and wall energies, −K is
// their Hessian: the added operator is symmetric positive semidefinite in the energy norm
// and damps what made the explicit step unstable, as backward Euler does.
//
// K acts without being formed, in two parts, K = K_elastic + K_interaction:
// - the elastic and wall forces by a one-sided difference along δx = Δt U I û,
//     K δx ≈ [f(x^n + σ δx) − f(x^n)] / σ,   σ = h / max_I |δx_I|,
//   with f(x^n) evaluated once per step and h = 1e-6 μm. Its truncation error is about
//   h/ℓ ≈ 3e-6 of K δx for the shortest length ℓ of the forces (the cells' elements
//   ≈ 0.3 μm), its round-off about ε |f| / (h |K|) ≲ 1e-9;
// - the Morse interaction exactly, from each pair's Hessian block found once per step
//   (kernels/morse_stiffness.hpp). Differencing it too cost one exponential per pair per
//   action: with 64 cells in contact, 85 % of the fluid solve's time.
// Each action costs one evaluation of the elastic (and wall) forces, one stream over the
// Morse pairs, one interpolation and one spread.
// In scaled residual units (forces / (P L²)) the action on the scaled state û is
//     Ŝ û = −S K (Δt U I û) / (P L²).
#include <Kokkos_Core.hpp>
#include <functional>

#include "cells/cell_population.hpp"
#include "cells/surface_interaction.hpp"
#include "coupling/cell_forces.hpp"
#include "coupling/rkpm_coupler.hpp"
#include "coupling/wall_repulsion.hpp"
#include "fluid/boundary_conditions.hpp"
#include "solver/linear_operator.hpp"

namespace rouleau {

// out = the elastic forces on the cell nodes (with the global constraints) and the wall
// repulsion (when `wall`) at `positions` [pN] (CellPopulation::internal_forces_at: the
// population's own state is left as it is); `scratch` holds the wall's part on its way. These are −∂E/∂x of the cells' energy less the interaction's, the forces
// whose stiffness CellStiffness differences. With a share of the cells on this rank
// (CellPopulation::share_work), the share's: the wall's forces at the nodes n with
// computed_nodes(n) = 1 alone (every node when `computed_nodes` is empty).
void differenced_forces(const CellPopulation& population, const WallRepulsion* wall,
                        const CellPopulation::ConstNodeVectors& positions, const CellPopulation::NodeVectors& scratch,
                        const CellPopulation::NodeVectors& out, const Kokkos::View<const int*>& computed_nodes = {});

class CellStiffness final : public LinearOperator {
 public:
  using NodeVectors = Kokkos::View<double* [3]>;
  using ConstNodeVectors = Kokkos::View<const double* [3]>;
  // forces(positions, out): the position-dependent forces on the cell nodes [pN] at
  // `positions` that the operator differences (elastic, wall; not the interaction's),
  // written to out; it must not change the cells' state.
  using ForceEvaluation = std::function<void(const NodeVectors& positions, const NodeVectors& out)>;

  // `nodes`: the number of cell nodes. `rkpm` holds the supports at x^n. `interaction`
  // (or null) adds its exact stiffness. All must outlive the operator.
  CellStiffness(int nodes, const RkpmCoupler& rkpm, ForceEvaluation forces, SurfaceInteraction* interaction,
                const FluidScales& scales);

  // Linearizes about the positions x^n (copies them, evaluates the differenced forces there
  // and the interaction's pair stiffness) for a fluid solve over the step Δt [s]. The
  // differences displace the operator's own copy of the positions, never the cells'.
  void linearize(const ConstNodeVectors& positions, double dt);
  // The difference step h [μm] (the largest node displacement of a difference).
  static constexpr double difference_step = 1e-6;

  // y = Ŝ x on the fluid's unknowns (4 per dof node; pressure rows zero).
  void apply(const Kokkos::View<const double*>& x, const Kokkos::View<double*>& y) const override;
  // force_change(n) = (K δx)_n [pN], δx = Δt U I x: the change of the cells' forces over the
  // step when the fluid's scaled state is x (apply() spreads −force_change / (P L²)).
  void force_change(const Kokkos::View<const double*>& x, const NodeVectors& force_change) const;
  // change(n) = (K δx)_n [pN] for node moves δx = `moves` [μm] (the same difference and
  // exact interaction part; the sub-grid film model's implicit update uses it).
  void moves_force_change(const NodeVectors& moves, const NodeVectors& change) const;

  // Evaluations of the differenced forces made so far (one per action and one per
  // linearization).
  long evaluations() const { return evaluations_; }

 private:
  const RkpmCoupler& rkpm_;
  ForceEvaluation forces_;
  SurfaceInteraction* interaction_;
  FluidScales scales_;
  double dt_ = 0.0;
  // x^n, and x^n + σ δx of a difference (the operator's own copies).
  NodeVectors base_positions_, displaced_positions_;
  NodeVectors base_forces_, displacement_, displaced_forces_, change_, interaction_change_;
  mutable long evaluations_ = 0;
};

}  // namespace rouleau
