#pragma once
// The pair loop of the cell–cell surface interaction (paper eq. 11 by nodal quadrature),
// generic in the pair physics (a Potential with force(r) = −φ'(r) and force_and_energy, per
// pair of cell kinds) and in the list: a full list (each point sums its own force, no
// scatter; each pair computed twice) or a half list (each pair once, the force on j
// scattered). For the pair (i, j), d = x_i − x_j, r = |d| < r_c:
//   F_i = w_i w_j f(r) d / r = −F_j,    E_ij = w_i w_j φ(r).
#include <Kokkos_Core.hpp>
#include <cmath>
#include <type_traits>

#include "kernels/interleaved_rows.hpp"
#include "kernels/launch_tags.hpp"
#include "kernels/surface_neighbors.hpp"

namespace rouleau {

template <class List, class Potential, class Scatter>
struct SurfacePairForceFunctor {
  Kokkos::View<const double* [3]> point_positions;  // surface points (point, 3) [μm]
  Kokkos::View<const double*> point_weight;         // area weight w [μm²] (reference surface)
  Kokkos::View<const int*> point_kind;          // the point's cell kind
  Kokkos::View<const Potential**> potentials;   // (kind, kind)
  Kokkos::View<const int*> neighbor_offsets;    // CSR rows (point + 1)
  Kokkos::View<const int*> neighbors;           // CSR columns: surface points
  Kokkos::View<double* [3]> point_forces;       // full list: F (point, 3) [pN], written
  Scatter scattered_forces;                     // half list: F (point, 3), accumulated
  InterleavedRows rows;                         // the order of the rows (interleaved_rows.hpp)

  // The forces of point i's pairs; returns their energy (each pair's whole energy for a
  // half list, half of it for a full list, so that the sums are the total).
  template <bool with_energy>
  KOKKOS_INLINE_FUNCTION double point_pairs(const int i) const {
    const double x[3] = {point_positions(i, 0), point_positions(i, 1), point_positions(i, 2)};
    const double w_i = point_weight(i);
    const int kind_i = point_kind(i);
    double force_i[3] = {0.0, 0.0, 0.0};
    double energy = 0.0;
    for (int k = neighbor_offsets(i); k < neighbor_offsets(i + 1); ++k) {
      const int j = neighbors(k);
      const double d[3] = {x[0] - point_positions(j, 0), x[1] - point_positions(j, 1), x[2] - point_positions(j, 2)};
      const double r_squared = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const Potential& potential = potentials(kind_i, point_kind(j));
      if (r_squared >= potential.cutoff * potential.cutoff) continue;
      const double r = sqrt(r_squared);
      const double weights = w_i * point_weight(j);
      double pair_energy = 0.0;
      const double force = with_energy ? potential.force_and_energy(r, pair_energy) : potential.force(r);
      // F_i = w_i w_j f(r) d / r
      const double scale = weights * force / r;
      for (int c = 0; c < 3; ++c) force_i[c] += scale * d[c];
      if (std::is_same<List, HalfList>::value) {
        auto access = scattered_forces.access();
        for (int c = 0; c < 3; ++c) access(j, c) -= scale * d[c];
      }
      if (with_energy) energy += weights * pair_energy;
    }
    if (std::is_same<List, HalfList>::value) {
      auto access = scattered_forces.access();
      for (int c = 0; c < 3; ++c) access(i, c) += force_i[c];
    } else {
      for (int c = 0; c < 3; ++c) point_forces(i, c) = force_i[c];
    }
    return std::is_same<List, HalfList>::value ? energy : 0.5 * energy;
  }

  KOKKOS_INLINE_FUNCTION void operator()(ForcesOnly, const int i) const {
    const int row = rows.row_of(i);
    if (row < rows.num_points) point_pairs<false>(row);
  }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesAndEnergy, const int i, double& energy) const {
    const int row = rows.row_of(i);
    if (row < rows.num_points) energy += point_pairs<true>(row);
  }
};

}  // namespace rouleau
