#pragma once
// Neighbour search between the surface points of different cells: a cell list (uniform
// bins) and a CSR list of the pairs within the search radius r.
//
// Points are binned by b = (i_x, i_y, i_z) = ⌊(x − lower)/bin_size⌋ (clamped to the grid)
// and sorted by (bin, point index), so every list comes out the same on every run and
// thread count. Bins are r/2 wide and searched `reach` = 2 deep: the 5³ bins around a
// point cover (5 r/2)³ = 15.6 r³, against 27 r³ for the 3³ bins of edge r, so fewer
// distances are tested. The neighbours of point i are the points j of those bins with
// cell(j) ≠ cell(i) and |x_i − x_j| < r: all of them (a full list, row i holds each pair
// once from each side) or only j > i (a half list, each pair once). The lists are built
// in two passes over the same loop: count, exclusive scan into offsets, fill.
#include <Kokkos_Core.hpp>
#include <type_traits>

namespace rouleau {

struct BinGrid {
  double lower[3];    // [μm]
  double bin_size;    // [μm]
  int bins[3];        // per direction
  int reach;          // bins searched on each side: ⌈search radius / bin_size⌉

  KOKKOS_INLINE_FUNCTION int coordinate(const double x, const int d) const {
    int i = static_cast<int>(floor((x - lower[d]) / bin_size));
    return i < 0 ? 0 : (i >= bins[d] ? bins[d] - 1 : i);
  }
  KOKKOS_INLINE_FUNCTION int bin_of(const double x[3]) const {
    return (coordinate(x[2], 2) * bins[1] + coordinate(x[1], 1)) * bins[0] + coordinate(x[0], 0);
  }
  int num_bins() const { return bins[0] * bins[1] * bins[2]; }
};

struct FullList {};
struct HalfList {};
// A half list for a share of the rows (SurfaceInteraction::share_rows): the pair loops
// treat it as a HalfList.
struct BalancedHalfList {};

// Whether a balanced half list keeps pair (i, j), i ≠ j, in row i (see for_each_neighbor).
KOKKOS_INLINE_FUNCTION bool balanced_half_list_row(const int i, const int j) {
  return (i < j) == (((i + j) & 1) == 0);
}

// Visits the neighbours of point i (List: FullList, HalfList or BalancedHalfList) in a
// fixed order: the bins within `reach` of i's in z, y, x order, each bin's points in
// ascending index. A half list holds each pair (i, j), i < j, once: in row i. Points are
// numbered cell by cell, so the rows of a block of cells hold all the pairs between it and
// later cells and none with earlier ones; a balanced half list puts the pair in row i when
// i + j is even and in row j when it is odd, so that a block's rows (a rank's share of the
// cells, SurfaceInteraction::share_rows) hold about half of either. It costs 1.1–1.4× per
// pair on one thread (bench_morse, 100 and 1000 cells), which is why it is not the default.
template <class List, class PositionView, class PointView, class CellView, class BinView, class Visit>
KOKKOS_INLINE_FUNCTION void for_each_neighbor(const int i, const BinGrid& grid, const double radius_squared,
                                              const PositionView& point_positions, const CellView& point_cell,
                                              const BinView& bin_offsets, const PointView& sorted_points,
                                              const Visit& visit) {
  const double x[3] = {point_positions(i, 0), point_positions(i, 1), point_positions(i, 2)};
  const int home[3] = {grid.coordinate(x[0], 0), grid.coordinate(x[1], 1), grid.coordinate(x[2], 2)};
  const int cell_i = point_cell(i);
  for (int bz = home[2] - grid.reach; bz <= home[2] + grid.reach; ++bz) {
    if (bz < 0 || bz >= grid.bins[2]) continue;
    for (int by = home[1] - grid.reach; by <= home[1] + grid.reach; ++by) {
      if (by < 0 || by >= grid.bins[1]) continue;
      for (int bx = home[0] - grid.reach; bx <= home[0] + grid.reach; ++bx) {
        if (bx < 0 || bx >= grid.bins[0]) continue;
        const int bin = (bz * grid.bins[1] + by) * grid.bins[0] + bx;
        for (int k = bin_offsets(bin); k < bin_offsets(bin + 1); ++k) {
          const int j = sorted_points(k);
          if (point_cell(j) == cell_i) continue;
          if (std::is_same<List, HalfList>::value && j <= i) continue;
          if (std::is_same<List, BalancedHalfList>::value && !balanced_half_list_row(i, j)) continue;
          const double d0 = x[0] - point_positions(j, 0), d1 = x[1] - point_positions(j, 1),
                       d2 = x[2] - point_positions(j, 2);
          if (d0 * d0 + d1 * d1 + d2 * d2 < radius_squared) visit(j);
        }
      }
    }
  }
}

}  // namespace rouleau
