#pragma once
// The largest eigenvalue λ_max of the mass-scaled stiffness A = M^(−1/2) K M^(−1/2) of the
// static solve (cells/static_equilibrium.hpp), which limits its FIRE step (Δt < 2/√λ_max):
// power iteration z ← A z / |A z|, with the product K z' by a forward difference of the
// conservative forces f = f_int + f_pressure (cells/equilibrium_forces.hpp),
//   K z' ≈ −(f(x0 + ε z') − f(x0)) / ε,   z' = M^(−1/2) z,
// ε such that the largest nodal displacement ε |z'_a| is 1e-7 μm; λ ≈ z·Az / z·z. The
// pull's geometric stiffness F/|p| is left out (small).
#include <Kokkos_Core.hpp>

#include "cells/equilibrium_forces.hpp"

namespace rouleau {

template <class ExecSpace>
class BasicStiffnessEstimate {
 public:
  using NodeVectors = typename BasicEquilibriumForces<ExecSpace>::NodeVectors;

  // `forces` (whose positions the trial displacements move and restore) must outlive it.
  BasicStiffnessEstimate(BasicEquilibriumForces<ExecSpace>& forces, const Kokkos::View<double*>& inverse_sqrt_mass);

  // λ_max at the forces' current positions after `iterations` power iterations, from a
  // pseudo-random start or (warm_start) from the last iterate; 0 when none could be made.
  // The positions and their forces are restored; force_evaluations counts the evaluations.
  double largest_eigenvalue(int iterations, bool warm_start, int& force_evaluations);

  // ---- the device kernels (public: CUDA lambdas may not live in private members)
  // z = a reproducible pseudo-random vector.
  void random_start();
  // max_a |z_a| / √m_a.
  double largest_scaled_iterate() const;
  // x = x0 + ε M^(−1/2) z.
  void displace(double epsilon);
  // One power iteration at displacement ε: az = A z, eigenvalue = z·Az / z·z, z = az / |az|;
  // false (z and eigenvalue as they were) when z or A z vanished.
  bool power_step(double epsilon, double& eigenvalue, int& force_evaluations);

 private:
  BasicEquilibriumForces<ExecSpace>& forces_;
  Kokkos::View<double*> inverse_sqrt_mass_;
  NodeVectors z_, az_, x0_, f0_, f_;
};

extern template class BasicStiffnessEstimate<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
