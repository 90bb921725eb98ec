#pragma once
// The stiffness of the cell–cell surface interaction (paper eq. 11 by nodal quadrature):
// the exact change of the pair forces under small moves of the surface points, for the
// semi-implicit coupling (coupling/cell_stiffness.hpp).
//
// For the pair (i, j), d = x_i − x_j, r = |d|, F_i = w_i w_j f(r) d/r = −F_j. Under moves
// δx, with δd = δx_i − δx_j, the linear change is
//   δF_i = w_i w_j [ (f/r) δd + (f' − f/r) (d̂·δd) d̂ ] = a δd + b (d·δd) d = −δF_j,
//   a = w_i w_j f(r)/r,   b = w_i w_j (f'(r) − f(r)/r) / r²,
// a symmetric 3×3 block per pair (−K is the Hessian of the pair energy w_i w_j φ(r)).
// The pairs within r_c and their coefficients (a, b) are found once per linearization
// (one exponential per pair); each action then streams them, with no exponential, square
// root or division.
#include <Kokkos_Core.hpp>
#include <cmath>
#include <type_traits>

#include "kernels/interleaved_rows.hpp"
#include "kernels/surface_neighbors.hpp"

namespace rouleau {

// The pairs of the list within the cut-off, in a CSR of their own (the list also holds
// the skin's pairs, a third of its entries), with their coefficients (a, b) at the current
// positions. Two launches: CountPairsInRange writes each row's count to pair_offsets(i)
// (then scanned into offsets), FillPairsInRange the columns and coefficients.
struct CountPairsInRange {};
struct FillPairsInRange {};

template <class Potential>
struct SurfacePairStiffnessFunctor {
  Kokkos::View<const double* [3]> point_positions;  // (point, 3) [μm]
  Kokkos::View<const double*> point_weight;         // w [μm²]
  Kokkos::View<const int*> point_kind;
  Kokkos::View<const Potential**> potentials;       // (kind, kind)
  Kokkos::View<const int*> neighbor_offsets;        // the list: CSR rows (point + 1)
  Kokkos::View<const int*> neighbors;               // the list: CSR columns
  Kokkos::View<int*> pair_offsets;                  // in range: counts, then CSR rows (point + 1)
  Kokkos::View<int*> pair_neighbors;                // in range: CSR columns, written
  Kokkos::View<double* [2]> pair_coefficients;      // (pair, [a pN/μm, b pN/μm³]), written

  // Calls in_range(j, potential, r²) for each list entry (i, j) with r < r_c.
  template <class InRange>
  KOKKOS_INLINE_FUNCTION void for_each_pair_in_range(const int i, const InRange& in_range) const {
    const double x[3] = {point_positions(i, 0), point_positions(i, 1), point_positions(i, 2)};
    const int kind_i = point_kind(i);
    for (int k = neighbor_offsets(i); k < neighbor_offsets(i + 1); ++k) {
      const int j = neighbors(k);
      const double d[3] = {x[0] - point_positions(j, 0), x[1] - point_positions(j, 1), x[2] - point_positions(j, 2)};
      const double r_squared = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const Potential& potential = potentials(kind_i, point_kind(j));
      if (r_squared < potential.cutoff * potential.cutoff) in_range(j, potential, r_squared);
    }
  }

  KOKKOS_INLINE_FUNCTION void operator()(CountPairsInRange, const int i) const {
    int count = 0;
    for_each_pair_in_range(i, [&](int, const Potential&, double) { ++count; });
    pair_offsets(i) = count;
  }

  KOKKOS_INLINE_FUNCTION void operator()(FillPairsInRange, const int i) const {
    const double w_i = point_weight(i);
    int slot = pair_offsets(i);
    for_each_pair_in_range(i, [&](const int j, const Potential& potential, const double r_squared) {
      const double r = sqrt(r_squared);
      const double weights = w_i * point_weight(j);
      double slope = 0.0;
      const double force = potential.force_and_slope(r, slope);
      // a = w_i w_j f/r,  b = w_i w_j (f' − f/r)/r²
      const double a = weights * force / r;
      pair_neighbors(slot) = j;
      pair_coefficients(slot, 0) = a;
      pair_coefficients(slot, 1) = (weights * slope - a) / r_squared;
      ++slot;
    });
  }
};

// The force change δF of every surface point under point moves δx, from the coefficients
// and pairs of SurfacePairStiffnessFunctor at `point_positions`. A full list writes each point's
// sum; a half list (each pair once) scatters −δF_i onto j and launches over
// rows.extent() indices in the interleaved order.
template <class List, class Scatter>
struct SurfacePairForceChangeFunctor {
  Kokkos::View<const double* [3]> point_positions;      // at the linearization [μm]
  Kokkos::View<const double* [3]> point_displacements;  // δx (point, 3) [μm]
  Kokkos::View<const int*> pair_offsets;                // the pairs in range: CSR rows
  Kokkos::View<const int*> pair_neighbors;              // CSR columns
  Kokkos::View<const double* [2]> pair_coefficients;    // (pair, [a, b])
  Kokkos::View<double* [3]> point_force_changes;        // full list: δF (point, 3) [pN], written
  Scatter scattered_force_changes;                      // half list: δF, accumulated
  InterleavedRows rows;

  KOKKOS_INLINE_FUNCTION void point_pairs(const int i) const {
    const double x[3] = {point_positions(i, 0), point_positions(i, 1), point_positions(i, 2)};
    const double dx[3] = {point_displacements(i, 0), point_displacements(i, 1), point_displacements(i, 2)};
    double change_i[3] = {0.0, 0.0, 0.0};
    for (int k = pair_offsets(i); k < pair_offsets(i + 1); ++k) {
      const double a = pair_coefficients(k, 0), b = pair_coefficients(k, 1);
      const int j = pair_neighbors(k);
      const double d[3] = {x[0] - point_positions(j, 0), x[1] - point_positions(j, 1), x[2] - point_positions(j, 2)};
      const double dd[3] = {dx[0] - point_displacements(j, 0), dx[1] - point_displacements(j, 1),
                            dx[2] - point_displacements(j, 2)};
      // δF_i = a δd + b (d·δd) d
      const double along = b * (d[0] * dd[0] + d[1] * dd[1] + d[2] * dd[2]);
      const double change[3] = {a * dd[0] + along * d[0], a * dd[1] + along * d[1], a * dd[2] + along * d[2]};
      for (int c = 0; c < 3; ++c) change_i[c] += change[c];
      if (std::is_same<List, HalfList>::value) {
        auto access = scattered_force_changes.access();
        for (int c = 0; c < 3; ++c) access(j, c) -= change[c];
      }
    }
    if (std::is_same<List, HalfList>::value) {
      auto access = scattered_force_changes.access();
      for (int c = 0; c < 3; ++c) access(i, c) += change_i[c];
    } else {
      for (int c = 0; c < 3; ++c) point_force_changes(i, c) = change_i[c];
    }
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const int row = rows.row_of(i);
    if (row < rows.num_points) point_pairs(row);
  }
};

}  // namespace rouleau
