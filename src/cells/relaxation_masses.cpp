// The dynamic-relaxation masses of the static solve (cells/relaxation_masses.hpp).
#include "cells/relaxation_masses.hpp"

#include "kernels/tet4.hpp"
#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

template <class ExecSpace>
BasicRelaxationMasses<ExecSpace>::BasicRelaxationMasses(const BasicCellPopulation<ExecSpace>& cells)
    : mass_("rouleau::StaticEquilibrium::mass", cells.num_nodes()),
      inverse_sqrt_mass_("rouleau::StaticEquilibrium::inverse_sqrt_mass", cells.num_nodes()) {
  compute(cells);
}

template <class ExecSpace>
void BasicRelaxationMasses<ExecSpace>::compute(const BasicCellPopulation<ExecSpace>& cells) {
  ProfilingRegion region("rouleau::StaticEquilibrium::masses");
  // Block-Gershgorin bound of the small-strain stiffness of one tetrahedron per unit
  // P-wave modulus (λ + 2μ): its block K_ab = V0 [(λ + μ) ∇N_a ⊗ ∇N_b + μ (∇N_a·∇N_b) I]
  // has norm ≤ V0 (λ + 2μ) |∇N_a| |∇N_b|, so m_a = Σ_e V0 |∇N_a| Σ_b |∇N_b| bounds row a.
  auto element_nodes = cells.element_nodes();
  auto inverse_edge_matrix = cells.inverse_edge_matrix();
  auto reference_volume = cells.reference_volume();
  auto mass = mass_;
  Kokkos::deep_copy(mass, 0.0);
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::masses", Kokkos::RangePolicy<ExecSpace>(0, cells.num_elements()),
      KOKKOS_LAMBDA(const int e) {
        Mat3 inverse;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) inverse.m[i][j] = inverse_edge_matrix(e, i, j);
        double gradient[4][3];
        Tet4::shape_gradients(inverse, gradient);
        double length[4], total = 0.0;
        for (int a = 0; a < 4; ++a) {
          length[a] =
              sqrt(gradient[a][0] * gradient[a][0] + gradient[a][1] * gradient[a][1] + gradient[a][2] * gradient[a][2]);
          total += length[a];
        }
        for (int a = 0; a < 4; ++a)
          Kokkos::atomic_add(&mass(element_nodes(e, a)), reference_volume(e) * length[a] * total);
      });
  auto inverse_sqrt_mass = inverse_sqrt_mass_;
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::inverse_sqrt_mass", Kokkos::RangePolicy<ExecSpace>(0, cells.num_nodes()),
      KOKKOS_LAMBDA(const int a) { inverse_sqrt_mass(a) = mass(a) > 0.0 ? 1.0 / sqrt(mass(a)) : 0.0; });
  Kokkos::fence();
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicRelaxationMasses)

}  // namespace rouleau
