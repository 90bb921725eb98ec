#pragma once
// The forces of the static solve (cells/static_equilibrium.hpp) at the solver's own copy x
// of the cells' positions (the population's own are written once, at the end of a solve):
//
//   r(x) = f_int(x) + f_pressure(x) + f_dead + f_pull(x),
//
// f_int the population's internal forces (CellPopulation::internal_forces_at: the
// population's state is left as it is), f_dead the dead loads, f_pull,a = F w_a p/|p| the
// pull between two node groups (p = Σ_a w_a x_a), and, with the enclosed-volume
// constraint, the forces of each cell's internal pressure,
//   f_pressure,a = p_c ∂V_c/∂x_a,   p_c = λ_c − k (V_c − V0_c),
// with the augmented Lagrangian's multipliers λ_c and penalty k.
#include <Kokkos_Core.hpp>
#include <array>
#include <vector>

#include "cells/cell_population.hpp"

namespace rouleau {

template <class ExecSpace>
class BasicEquilibriumForces {
 public:
  using NodeVectors = Kokkos::View<double* [3]>;

  // Reads `cells` (which must outlive it), never writes them.
  explicit BasicEquilibriumForces(const BasicCellPopulation<ExecSpace>& cells);

  // x (node, 3) [μm]: the solver's positions, which the relaxation moves.
  const NodeVectors& positions() const { return positions_; }
  void start_from(const Kokkos::View<const double* [3]>& positions) { Kokkos::deep_copy(positions_, positions); }

  // ---- the loads (BasicStaticEquilibrium's set_pull and dead_loads say what they are)
  const NodeVectors& dead_loads() const { return dead_loads_; }
  void set_pull(const Kokkos::View<double*>& signed_weights, double force);
  void clear_pull() { pull_force_ = 0.0; }
  double pull_force() const { return pull_force_; }
  const Kokkos::View<double*>& pull_weights() const { return pull_weights_; }
  // L = F + ½ Σ_a |f_dead,a| [pN].
  double applied_load() const;
  // Σ_a f_dead,a [pN] (zero for balanced loads).
  std::array<double, 3> dead_load_sum() const;
  // p = Σ_a w_a x_a at x.
  std::array<double, 3> pull_vector() const;
  // F p/|p| [pN] (zero without a pull or while p = 0).
  std::array<double, 3> pull_along(const std::array<double, 3>& p) const;

  // ---- the enclosed-volume constraint
  // Penalty k [pN/μm⁵] (0: off); V0_c from the reference configuration; λ_c = p_c = 0.
  void set_volume_constraint(double stiffness);
  bool holds_volumes() const { return volume_stiffness_ > 0.0; }
  // λ_c ← p_c (the augmented Lagrangian's update).
  void update_volume_multipliers();
  // max_c |V_c − V0_c| / V0_c at the last evaluate().
  double largest_volume_error() const;
  // p_c [Pa] at the last evaluate() (zero without the constraint).
  const std::vector<double>& cell_pressures() const { return cell_pressures_; }

  // ---- the forces at x
  // f_int into internal_forces() and, with the volume constraint, f_pressure into
  // pressure_forces().
  void evaluate();
  const NodeVectors& internal_forces() const { return internal_forces_; }
  const NodeVectors& pressure_forces() const { return pressure_forces_; }
  // out = f_int + f_pressure.
  void conservative_forces(const NodeVectors& out) const;

  // (public: CUDA lambdas may not live in private members)
  void compute_pressure_forces();

 private:
  using Scatter = typename BasicCellPopulation<ExecSpace>::Scatter;

  const BasicCellPopulation<ExecSpace>& cells_;
  NodeVectors positions_, internal_forces_, pressure_forces_, dead_loads_;
  Kokkos::View<double*> pull_weights_;
  double pull_force_ = 0.0;
  double volume_stiffness_ = 0.0;
  std::vector<double> reference_volumes_, volume_multipliers_, cell_pressures_, cell_volumes_;
  // The pressure forces as the global volume constraint's: P_c = −p_c, no tension.
  Kokkos::View<int*> cell_first_node_;
  Kokkos::View<double*> constraint_pressures_, no_tensions_;
  Scatter pressure_scatter_;
};

extern template class BasicEquilibriumForces<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
