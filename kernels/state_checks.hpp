#pragma once
// Health checks of the state after a step (docs/running.md, "Divergence"): the first entry of a
// field that is NaN or Inf, and the most compressed solid element, J = det F smallest
// (J ≤ 0: the tetrahedron is inverted). Each is one reduction; the run stops at the step
// where one fails and names what it found.
#include <Kokkos_Core.hpp>
#include <climits>

#include "kernels/mat3.hpp"
#include "kernels/tet4.hpp"

namespace rouleau {

// x − x is 0 for every finite x and NaN for NaN and ±Inf, and NaN compares unequal to
// everything (this needs IEEE arithmetic: rouleau is not built with -ffast-math).
KOKKOS_INLINE_FUNCTION bool is_finite_value(const double x) { return x - x == 0.0; }

// The smallest row (first index) of `field` holding a non-finite entry, reduced with
// Kokkos::Min<int>; INT_MAX when every entry is finite. Rank 1 (a state vector) or rank
// 2 (node vectors).
template <class Field>
struct FirstNonFiniteRowFunctor {
  Field field;

  KOKKOS_INLINE_FUNCTION void operator()(const int row, int& first) const {
    bool finite = true;
    if constexpr (Field::rank == 1) {
      finite = is_finite_value(field(row));
    } else {
      for (int c = 0; c < static_cast<int>(field.extent(1)); ++c) finite = finite && is_finite_value(field(row, c));
    }
    if (!finite && row < first) first = row;
  }
};

// The first non-finite row of `field`, or −1 when all are finite.
template <class ExecSpace, class Field>
int first_non_finite_row(const ExecSpace& space, const Field& field, const char* label) {
  int first = INT_MAX;
  Kokkos::parallel_reduce(label, Kokkos::RangePolicy<ExecSpace>(space, 0, static_cast<int>(field.extent(0))),
                          FirstNonFiniteRowFunctor<Field>{field}, Kokkos::Min<int>(first));
  return first == INT_MAX ? -1 : first;
}

// The element with the smallest volume ratio J = det F = det(D_s D_m⁻¹) (Tet4), reduced
// with Kokkos::MinLoc. J = V/V0: 1 at rest, → 0 when the tetrahedron flattens, < 0 when
// it is turned inside out (the neo-Hookean energy of paper eq. 2 depends on J only
// through J², so it does not resist inversion and the forces stay finite: this check is
// the only one that sees it).
struct SmallestVolumeRatioFunctor {
  using Reducer = Kokkos::MinLoc<double, int>;
  using value_type = Reducer::value_type;

  Kokkos::View<const double* [3]> positions;               // x (node, 3) [μm]
  Kokkos::View<const int* [4]> element_nodes;              // (element, 4)
  Kokkos::View<const double* [3][3]> inverse_edge_matrix;  // D_m⁻¹ (element, 3, 3) [1/μm]

  KOKKOS_INLINE_FUNCTION void operator()(const int e, value_type& smallest) const {
    double x[4][3];
    Mat3 inverse;
    Tet4::gather(e, positions, element_nodes, inverse_edge_matrix, x, inverse);
    const double j = determinant(Tet4::deformation_gradient(x, inverse));
    // NaN positions give a NaN J, which is not smaller than anything: report it as the
    // lowest double.
    const double ratio = is_finite_value(j) ? j : -1.7976931348623157e308;
    if (ratio < smallest.val) {
      smallest.val = ratio;
      smallest.loc = e;
    }
  }
};

}  // namespace rouleau
