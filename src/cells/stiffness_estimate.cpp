// λ_max of the static solve's mass-scaled stiffness by power iteration on finite
// differences of its forces (cells/stiffness_estimate.hpp).
#include "cells/stiffness_estimate.hpp"

#include <cmath>

#include "kernels/static_relaxation.hpp"
#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

template <class ExecSpace>
BasicStiffnessEstimate<ExecSpace>::BasicStiffnessEstimate(BasicEquilibriumForces<ExecSpace>& forces,
                                                          const Kokkos::View<double*>& inverse_sqrt_mass)
    : forces_(forces),
      inverse_sqrt_mass_(inverse_sqrt_mass),
      z_("rouleau::StaticEquilibrium::scratch_a", inverse_sqrt_mass.extent(0)),
      az_("rouleau::StaticEquilibrium::scratch_b", inverse_sqrt_mass.extent(0)),
      x0_("rouleau::StaticEquilibrium::x0", inverse_sqrt_mass.extent(0)),
      f0_("rouleau::StaticEquilibrium::f0", inverse_sqrt_mass.extent(0)),
      f_("rouleau::StaticEquilibrium::f", inverse_sqrt_mass.extent(0)) {}

template <class ExecSpace>
double BasicStiffnessEstimate<ExecSpace>::largest_eigenvalue(int iterations, bool warm_start, int& force_evaluations) {
  ProfilingRegion region("rouleau::StaticEquilibrium::largest_eigenvalue");
  Kokkos::deep_copy(x0_, forces_.positions());
  forces_.evaluate();
  ++force_evaluations;
  forces_.conservative_forces(f0_);
  if (!warm_start) random_start();
  double eigenvalue = 0.0;
  for (int k = 0; k < iterations; ++k) {
    const double largest = largest_scaled_iterate();
    if (!(largest > 0.0)) break;
    if (!power_step(1e-7 / largest, eigenvalue, force_evaluations)) break;
  }
  // Back to x0 and its forces.
  Kokkos::deep_copy(forces_.positions(), x0_);
  forces_.evaluate();
  ++force_evaluations;
  return eigenvalue;
}

template <class ExecSpace>
void BasicStiffnessEstimate<ExecSpace>::random_start() {
  auto z = z_;
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::power_start", Kokkos::RangePolicy<ExecSpace>(0, z.extent(0)),
      KOKKOS_LAMBDA(const int a) {
        for (int i = 0; i < 3; ++i)
          z(a, i) = static_relaxation::hashed_uniform(static_cast<unsigned int>(3 * a + i) * 2654435761U + 12345U);
      });
}

template <class ExecSpace>
double BasicStiffnessEstimate<ExecSpace>::largest_scaled_iterate() const {
  auto z = z_;
  auto inverse_sqrt_mass = inverse_sqrt_mass_;
  double largest = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::StaticEquilibrium::power_scale", Kokkos::RangePolicy<ExecSpace>(0, z.extent(0)),
      KOKKOS_LAMBDA(const int a, double& value) {
        const double d = sqrt(z(a, 0) * z(a, 0) + z(a, 1) * z(a, 1) + z(a, 2) * z(a, 2)) * inverse_sqrt_mass(a);
        if (d > value) value = d;
      },
      Kokkos::Max<double>(largest));
  return largest;
}

template <class ExecSpace>
void BasicStiffnessEstimate<ExecSpace>::displace(const double epsilon) {
  auto positions = forces_.positions();
  auto x0 = x0_;
  auto z = z_;
  auto inverse_sqrt_mass = inverse_sqrt_mass_;
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::power_trial", Kokkos::RangePolicy<ExecSpace>(0, z.extent(0)),
      KOKKOS_LAMBDA(const int a) {
        for (int i = 0; i < 3; ++i) positions(a, i) = x0(a, i) + epsilon * z(a, i) * inverse_sqrt_mass(a);
      });
}

template <class ExecSpace>
bool BasicStiffnessEstimate<ExecSpace>::power_step(const double epsilon, double& eigenvalue, int& force_evaluations) {
  displace(epsilon);
  forces_.evaluate();
  ++force_evaluations;
  forces_.conservative_forces(f_);
  static_relaxation::StiffnessActionFunctor functor;
  functor.forces = f_;
  functor.reference_forces = f0_;
  functor.z = z_;
  functor.inverse_sqrt_mass = inverse_sqrt_mass_;
  functor.az = az_;
  functor.inverse_epsilon = 1.0 / epsilon;
  const int n = static_cast<int>(z_.extent(0));
  const auto sums = static_relaxation::reduce3<ExecSpace>("rouleau::StaticEquilibrium::power_action", n, functor);
  if (!(sums[1] > 0.0) || !(sums[2] > 0.0)) return false;
  eigenvalue = sums[0] / sums[2];
  const double inverse_norm = 1.0 / std::sqrt(sums[1]);
  auto z = z_;
  auto az = az_;
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::power_normalize", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int a) {
        for (int i = 0; i < 3; ++i) z(a, i) = az(a, i) * inverse_norm;
      });
  return true;
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicStiffnessEstimate)

}  // namespace rouleau
