#pragma once
// The neighbours of a surface point among the points of other cells, for the Morse
// interaction's list (cells/surface_neighbor_list): the binned points
// (kernels/point_bins.hpp) in the bins around it, of another cell, closer than the
// search radius r. Row i of a full list holds each of its pairs once from each side; a
// half list holds each pair (i, j), i < j, once, in row i.
#include <Kokkos_Core.hpp>
#include <type_traits>

#include "kernels/point_bins.hpp"

namespace rouleau {

struct FullList {};
struct HalfList {};
// A half list for a share of the rows (SurfaceInteraction::share_rows): the pair loops
// treat it as a HalfList.
struct BalancedHalfList {};

// Whether a balanced half list keeps pair (i, j), i ≠ j, in row i (see for_each_neighbor).
KOKKOS_INLINE_FUNCTION bool balanced_half_list_row(const int i, const int j) {
  return (i < j) == (((i + j) & 1) == 0);
}

// Visits the neighbours of point i (List: FullList, HalfList or BalancedHalfList) in the
// fixed order of the bins (kernels/point_bins.hpp). Points are numbered cell by cell, so the rows of a block of cells hold all the pairs between it and
// later cells and none with earlier ones; a balanced half list puts the pair in row i when
// i + j is even and in row j when it is odd, so that a block's rows (a rank's share of the
// cells, SurfaceInteraction::share_rows) hold about half of either. It costs 1.1–1.4× per
// pair on one thread (bench_morse, 100 and 1000 cells), which is why it is not the default.
template <class List, class PositionView, class CellView, class Binned, class Visit>
KOKKOS_INLINE_FUNCTION void for_each_neighbor(const int i, const Binned& binned, const double radius_squared,
                                              const PositionView& point_positions, const CellView& point_cell,
                                              const Visit& visit) {
  const double x[3] = {point_positions(i, 0), point_positions(i, 1), point_positions(i, 2)};
  const int cell_i = point_cell(i);
  binned.for_each_point_near(x, [&](const int j) {
    if (point_cell(j) == cell_i) return;
    if (std::is_same<List, HalfList>::value && j <= i) return;
    if (std::is_same<List, BalancedHalfList>::value && !balanced_half_list_row(i, j)) return;
    const double d0 = x[0] - point_positions(j, 0), d1 = x[1] - point_positions(j, 1), d2 = x[2] - point_positions(j, 2);
    if (d0 * d0 + d1 * d1 + d2 * d2 < radius_squared) visit(j);
  });
}

}  // namespace rouleau
