// The static solve's forces at its own positions: internal, pressure, dead and pull
// (cells/equilibrium_forces.hpp).
#include "cells/equilibrium_forces.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernels/global_constraints.hpp"
#include "kernels/scatter_sum.hpp"
#include "kernels/static_relaxation.hpp"
#include "util/instantiate.hpp"
#include "util/view_transfer.hpp"

namespace rouleau {

template <class ExecSpace>
BasicEquilibriumForces<ExecSpace>::BasicEquilibriumForces(const BasicCellPopulation<ExecSpace>& cells)
    : cells_(cells),
      positions_("rouleau::StaticEquilibrium::positions", cells.num_nodes()),
      internal_forces_("rouleau::StaticEquilibrium::internal_forces", cells.num_nodes()),
      pressure_forces_("rouleau::StaticEquilibrium::constraint_forces", cells.num_nodes()),
      dead_loads_("rouleau::StaticEquilibrium::dead_loads", cells.num_nodes()),
      pull_weights_("rouleau::StaticEquilibrium::pull_weights", cells.num_nodes()),
      cell_pressures_(cells.num_cells(), 0.0),
      cell_first_node_(device_copy(cells.cell_first_node(), "rouleau::StaticEquilibrium::cell_first_node")),
      constraint_pressures_("rouleau::StaticEquilibrium::cell_pressures", cells.num_cells()),
      no_tensions_("rouleau::StaticEquilibrium::no_tensions", cells.num_cells()),
      pressure_scatter_("rouleau::StaticEquilibrium::pressure_scatter", cells.num_nodes()) {
  Kokkos::deep_copy(positions_, cells.positions());
}

template <class ExecSpace>
void BasicEquilibriumForces<ExecSpace>::set_pull(const Kokkos::View<double*>& signed_weights, double force) {
  if (static_cast<int>(signed_weights.extent(0)) != cells_.num_nodes())
    throw std::invalid_argument("rouleau::StaticEquilibrium::set_pull: one weight per node expected");
  if (!(force >= 0.0)) throw std::invalid_argument("rouleau::StaticEquilibrium::set_pull: force must be >= 0");
  Kokkos::deep_copy(pull_weights_, signed_weights);
  pull_force_ = force;
}

template <class ExecSpace>
double BasicEquilibriumForces<ExecSpace>::applied_load() const {
  auto dead = dead_loads_;
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::StaticEquilibrium::dead_load_magnitude", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_nodes()),
      KOKKOS_LAMBDA(const int a, double& s) {
        s += sqrt(dead(a, 0) * dead(a, 0) + dead(a, 1) * dead(a, 1) + dead(a, 2) * dead(a, 2));
      },
      sum);
  return pull_force_ + 0.5 * sum;
}

template <class ExecSpace>
std::array<double, 3> BasicEquilibriumForces<ExecSpace>::dead_load_sum() const {
  auto dead = dead_loads_;
  std::array<double, 3> sums{0.0, 0.0, 0.0};
  for (int i = 0; i < 3; ++i) {
    double s = 0.0;
    Kokkos::parallel_reduce(
        "rouleau::StaticEquilibrium::dead_load_sum", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_nodes()),
        KOKKOS_LAMBDA(const int a, double& value) { value += dead(a, i); }, s);
    sums[i] = s;
  }
  return sums;
}

template <class ExecSpace>
std::array<double, 3> BasicEquilibriumForces<ExecSpace>::pull_vector() const {
  static_relaxation::PullVectorFunctor functor;
  functor.positions = positions_;
  functor.pull_weights = pull_weights_;
  return static_relaxation::reduce3<ExecSpace>("rouleau::StaticEquilibrium::pull_vector", cells_.num_nodes(), functor);
}

template <class ExecSpace>
std::array<double, 3> BasicEquilibriumForces<ExecSpace>::pull_along(const std::array<double, 3>& p) const {
  // f_pull = F p/|p| on the weights (no pull while the groups coincide or F = 0)
  const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  const double scale = (pull_force_ > 0.0 && length > 0.0) ? pull_force_ / length : 0.0;
  return {scale * p[0], scale * p[1], scale * p[2]};
}

template <class ExecSpace>
void BasicEquilibriumForces<ExecSpace>::set_volume_constraint(double stiffness) {
  if (!(stiffness >= 0.0))
    throw std::invalid_argument("rouleau::StaticEquilibrium::set_volume_constraint: stiffness must be >= 0");
  volume_stiffness_ = stiffness;
  reference_volumes_.clear();
  for (const CellMeasures& m : cells_.measures_at(cells_.reference_positions())) reference_volumes_.push_back(m.volume);
  volume_multipliers_.assign(cells_.num_cells(), 0.0);
  cell_pressures_.assign(cells_.num_cells(), 0.0);
  Kokkos::deep_copy(pressure_forces_, 0.0);
}

template <class ExecSpace>
void BasicEquilibriumForces<ExecSpace>::update_volume_multipliers() {
  for (std::size_t c = 0; c < reference_volumes_.size(); ++c) volume_multipliers_[c] = cell_pressures_[c];
}

template <class ExecSpace>
double BasicEquilibriumForces<ExecSpace>::largest_volume_error() const {
  double largest = 0.0;
  for (std::size_t c = 0; c < reference_volumes_.size(); ++c)
    largest = std::max(largest, std::fabs(cell_volumes_[c] - reference_volumes_[c]) / reference_volumes_[c]);
  return largest;
}

template <class ExecSpace>
void BasicEquilibriumForces<ExecSpace>::evaluate() {
  cells_.internal_forces_at(positions_, internal_forces_);
  if (volume_stiffness_ <= 0.0) return;
  // p_c = λ_c − k (V_c − V0_c)
  const std::vector<CellMeasures> measures = cells_.measures_at(positions_);
  cell_volumes_.resize(measures.size());
  for (std::size_t c = 0; c < measures.size(); ++c) {
    cell_volumes_[c] = measures[c].volume;
    cell_pressures_[c] = volume_multipliers_[c] - volume_stiffness_ * (measures[c].volume - reference_volumes_[c]);
  }
  compute_pressure_forces();
}

template <class ExecSpace>
void BasicEquilibriumForces<ExecSpace>::compute_pressure_forces() {
  // The pressure p_c pushes the surface outward: f_a = p_c ∂V_c/∂x_a. This is the global
  // volume constraint's force −P_c ∂V_c/∂x_a (kernels/global_constraints.hpp) with
  // P_c = −p_c and no tension, per outer-surface triangle t = (x0, x1, x2), y = x − o:
  //   f_k += −P_c ∂V_t/∂x_k = (p_c / 6) y_{k+1} × y_{k+2}
  // (summed around node k it is p_c Σ_{t ∋ k} n_t / 3, n_t the area vector).
  auto host_pressures = Kokkos::create_mirror_view(constraint_pressures_);
  for (std::size_t c = 0; c < cell_pressures_.size(); ++c) host_pressures(c) = -cell_pressures_[c];
  Kokkos::deep_copy(constraint_pressures_, host_pressures);
  pressure_scatter_.reset();
  GlobalConstraintForceFunctor<Scatter> pressure{positions_,   cells_.surface_triangles(), cells_.triangle_cell(),
                                                 cell_first_node_, no_tensions_,            constraint_pressures_,
                                                 pressure_scatter_};
  Kokkos::parallel_for("rouleau::StaticEquilibrium::pressure_forces",
                       Kokkos::RangePolicy<ExecSpace>(0, cells_.num_surface_triangles()), pressure);
  gather_into(pressure_forces_, pressure_scatter_);
}

template <class ExecSpace>
void BasicEquilibriumForces<ExecSpace>::conservative_forces(const NodeVectors& out) const {
  auto internal = internal_forces_;
  auto pressure = pressure_forces_;
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::conservative_forces", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_nodes()),
      KOKKOS_LAMBDA(const int a) {
        for (int i = 0; i < 3; ++i) out(a, i) = internal(a, i) + pressure(a, i);
      });
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicEquilibriumForces)

}  // namespace rouleau
