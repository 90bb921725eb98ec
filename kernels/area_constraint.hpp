#pragma once
// A global area constraint per cell (Fedosov, Caswell & Karniadakis 2010, the global
// area term): the energy of cell c's outer surface, area A_c, reference area A0_c,
//
//   E_A = Σ_c k_A,c (A_c − A0_c)² / (2 A0_c),
//
// k_A the kind's area modulus [pN/μm] (0: off, the paper's scenes). Its forces,
// f_a = −∂E_A/∂x_a = −T_c ∂A_c/∂x_a, with the cell's isotropic tension
//   T_c = k_A,c (A_c − A0_c) / A0_c [pN/μm],
// and, per surface triangle t = (x0, x1, x2) (counter-clockwise, unit normal n̂),
//   A_t = |(x1 − x0) × (x2 − x0)| / 2,   ∂A_t/∂x_k = ½ n̂ × (x_{k+2} − x_{k+1})
// (indices mod 3). The area is invariant under rigid motions, so these forces add up to
// no net force and no net moment.
#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/cell_surface.hpp"
#include "kernels/launch_tags.hpp"

namespace rouleau {

// A_c = Σ_{t ∈ c} A_t, summed into a ScatterView (cell).
template <class Scatter>
struct CellAreaFunctor {
  Kokkos::View<const double* [3]> positions;  // (node, 3) [μm]
  Kokkos::View<const int* [3]> triangles;     // (triangle, 3)
  Kokkos::View<const int*> triangle_cell;     // (triangle)
  Scatter areas;                              // (cell) [μm²]

  KOKKOS_INLINE_FUNCTION void operator()(const int t) const {
    auto access = areas.access();
    access(triangle_cell(t)) += triangle_area(positions, triangles, t);
  }
};

// Per cell: T_c = k_A (A_c − A0_c) / A0_c into `tension`; with ForcesAndEnergy also
// E_A = Σ_c k_A (A_c − A0_c)² / (2 A0_c) [pN·μm].
struct AreaTensionFunctor {
  Kokkos::View<const double*> area;            // A_c [μm²]
  Kokkos::View<const double*> reference_area;  // A0_c [μm²]
  Kokkos::View<const double*> area_modulus;    // k_A,c [pN/μm]
  Kokkos::View<double*> tension;               // T_c [pN/μm]

  KOKKOS_INLINE_FUNCTION double cell_tension(const int c) const {
    if (area_modulus(c) == 0.0) {  // off (also for a cell without outer surface, A0 = 0)
      tension(c) = 0.0;
      return 0.0;
    }
    const double strain = (area(c) - reference_area(c)) / reference_area(c);
    tension(c) = area_modulus(c) * strain;
    return 0.5 * area_modulus(c) * reference_area(c) * strain * strain;
  }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesOnly, const int c) const { cell_tension(c); }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesAndEnergy, const int c, double& energy) const {
    energy += cell_tension(c);
  }
};

// f_k += −T_c ∂A_t/∂x_k on the three nodes of each surface triangle of a cell with T_c ≠ 0,
// summed into a ScatterView (node, 3) [pN].
template <class Scatter>
struct AreaConstraintForceFunctor {
  Kokkos::View<const double* [3]> positions;  // (node, 3) [μm]
  Kokkos::View<const int* [3]> triangles;     // (triangle, 3)
  Kokkos::View<const int*> triangle_cell;     // (triangle)
  Kokkos::View<const double*> tension;        // T_c (cell) [pN/μm]
  Scatter forces;                             // (node, 3) [pN]

  KOKKOS_INLINE_FUNCTION void operator()(const int t) const {
    const double cell_tension = tension(triangle_cell(t));
    if (cell_tension == 0.0) return;
    double y[3][3];
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) y[k][i] = positions(triangles(t, k), i);
    double n[3];
    triangle_area_vector(y, n);
    // −T ∂A_t/∂x_k = −(T / (2 A_t)) n × (x_{k+2} − x_{k+1}), with n the triangle's area
    // vector (|n| = A_t, n̂ = n / A_t).
    const double area = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(area > 0.0)) return;
    const double scale = -0.5 * cell_tension / area;
    auto access = forces.access();
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      const double e[3] = {y[k2][0] - y[k1][0], y[k2][1] - y[k1][1], y[k2][2] - y[k1][2]};
      const int node = triangles(t, k);
      access(node, 0) += scale * (n[1] * e[2] - n[2] * e[1]);
      access(node, 1) += scale * (n[2] * e[0] - n[0] * e[2]);
      access(node, 2) += scale * (n[0] * e[1] - n[1] * e[0]);
    }
  }
};

}  // namespace rouleau
