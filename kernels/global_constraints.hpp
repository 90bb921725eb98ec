#pragma once
// Global area and volume constraints per cell (Fedosov, Caswell & Karniadakis 2010, the
// global area and volume terms): the energy of cell c's outer surface, area A_c and
// enclosed volume V_c, reference values A0_c and V0_c,
//
//   E = Σ_c [ k_A,c (A_c − A0_c)² / (2 A0_c) + k_V,c (V_c − V0_c)² / (2 V0_c) ],
//
// k_A the kind's area modulus [pN/μm], k_V its volume modulus [Pa] (each 0: off, the
// paper's scenes). Its forces, f_a = −∂E/∂x_a = −T_c ∂A_c/∂x_a − P_c ∂V_c/∂x_a, with the
// cell's isotropic tension and pressure
//   T_c = k_A,c (A_c − A0_c) / A0_c [pN/μm],   P_c = k_V,c (V_c − V0_c) / V0_c [Pa],
// and, per surface triangle t = (x0, x1, x2) (counter-clockwise seen from outside, area
// vector n = ½ (x1 − x0) × (x2 − x0), unit normal n̂), with y_k = x_k − o for any point o
// fixed per cell (the sums over a closed surface do not depend on it):
//   A_t = |n|,                       ∂A_t/∂x_k = ½ n̂ × (x_{k+2} − x_{k+1}),
//   V_t = y0 · (y1 × y2) / 6,        ∂V_t/∂x_k = (y_{k+1} × y_{k+2}) / 6
// (indices mod 3). A and V are invariant under rigid motions, so these forces add up to
// no net force and no net moment.
//
// The volume term stands for the incompressible fluid a cell encloses: the fluid solver
// keeps it only to its discretization error (the interpolated velocity is not exactly
// divergence-free at the membrane, so a membrane under tension slowly loses volume), and
// k_V P_c supplies the interior pressure that holds it.
#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/cell_surface.hpp"
#include "kernels/launch_tags.hpp"

namespace rouleau {

// Per cell: T_c and P_c from the cell's surface sums (CellSurfaceSumsFunctor); with
// ForcesAndEnergy also E = Σ_c [k_A (A_c − A0_c)² / (2 A0_c) + k_V (V_c − V0_c)² / (2 V0_c)].
struct GlobalConstraintFunctor {
  Kokkos::View<const double* [sum_count]> sums;  // A_c, V_c, ... (cell, CellSurfaceSum)
  Kokkos::View<const double*> reference_area;                 // A0_c [μm²]
  Kokkos::View<const double*> reference_volume;               // V0_c [μm³]
  Kokkos::View<const double*> area_modulus;                   // k_A,c [pN/μm]
  Kokkos::View<const double*> volume_modulus;                 // k_V,c [Pa]
  Kokkos::View<double*> tension;                              // T_c [pN/μm]
  Kokkos::View<double*> pressure;                             // P_c [Pa]

  // k (X − X0)²/(2 X0) and k (X − X0)/X0 of one constraint; zero when off (also for a
  // cell without outer surface, X0 = 0).
  KOKKOS_INLINE_FUNCTION static double term(const double modulus, const double value, const double reference,
                                            double& multiplier) {
    if (modulus == 0.0) {
      multiplier = 0.0;
      return 0.0;
    }
    const double strain = (value - reference) / reference;
    multiplier = modulus * strain;
    return 0.5 * modulus * reference * strain * strain;
  }
  KOKKOS_INLINE_FUNCTION double cell_terms(const int c) const {
    return term(area_modulus(c), sums(c, surface_area), reference_area(c), tension(c)) +
           term(volume_modulus(c), sums(c, enclosed_volume), reference_volume(c), pressure(c));
  }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesOnly, const int c) const { cell_terms(c); }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesAndEnergy, const int c, double& energy) const {
    energy += cell_terms(c);
  }
};

// f_k += −T_c ∂A_t/∂x_k − P_c ∂V_t/∂x_k on the three nodes of each surface triangle of a
// cell with T_c or P_c ≠ 0, summed into a ScatterView (node, 3) [pN].
template <class Scatter>
struct GlobalConstraintForceFunctor {
  Kokkos::View<const double* [3]> positions;  // (node, 3) [μm]
  Kokkos::View<const int* [3]> triangles;     // (triangle, 3)
  Kokkos::View<const int*> triangle_cell;     // (triangle)
  Kokkos::View<const int*> cell_first_node;   // (cell): the point o of each cell
  Kokkos::View<const double*> tension;        // T_c (cell) [pN/μm]
  Kokkos::View<const double*> pressure;       // P_c (cell) [Pa]
  Scatter forces;                             // (node, 3) [pN]

  KOKKOS_INLINE_FUNCTION void operator()(const int t) const {
    const int cell = triangle_cell(t);
    const double cell_tension = tension(cell), cell_pressure = pressure(cell);
    if (cell_tension == 0.0 && cell_pressure == 0.0) return;
    const int origin = cell_first_node(cell);
    double y[3][3];
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) y[k][i] = positions(triangles(t, k), i) - positions(origin, i);
    double n[3];
    triangle_area_vector(y, n);
    const double area = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(area > 0.0)) return;
    // −T ∂A_t/∂x_k = −(T / (2 A_t)) n × (y_{k+2} − y_{k+1})
    const double area_scale = -0.5 * cell_tension / area;
    // −P ∂V_t/∂x_k = −(P / 6) y_{k+1} × y_{k+2}
    const double volume_scale = -cell_pressure / 6.0;
    auto access = forces.access();
    for (int k = 0; k < 3; ++k) {
      const double* a = y[(k + 1) % 3];
      const double* b = y[(k + 2) % 3];
      const double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
      const int node = triangles(t, k);
      access(node, 0) += area_scale * (n[1] * e[2] - n[2] * e[1]) + volume_scale * (a[1] * b[2] - a[2] * b[1]);
      access(node, 1) += area_scale * (n[2] * e[0] - n[0] * e[2]) + volume_scale * (a[2] * b[0] - a[0] * b[2]);
      access(node, 2) += area_scale * (n[0] * e[1] - n[1] * e[0]) + volume_scale * (a[0] * b[1] - a[1] * b[0]);
    }
  }
};

}  // namespace rouleau
