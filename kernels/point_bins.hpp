#pragma once
// The neighbour search of rouleau: points sorted into uniform bins over a box, and the
// visit of the points in the bins around a position. It finds the fluid nodes in a solid
// point's RKPM support (coupling/rkpm_coupler), the surface points of other cells within
// the Morse cut-off (cells/surface_neighbor_list) and the fluid node a rank owns nearest
// to a cell's centroid (distributed/fluid_distribution).
//
// A position x lies in bin b_d = ⌊(x_d − lower_d) / w_d⌋ along each direction d, wrapped
// on a periodic direction and clamped to the grid on the others; the bins are numbered
// (b_z n_y + b_y) n_x + b_x. The points of a bin are kept in ascending index, and a search
// visits the bins within `reach` of x's own in z, y, x order, so every search, and every
// list built from searches, comes out the same on every run and thread count. On a
// periodic direction with fewer than 2 reach + 1 bins the search visits each bin once, in
// ascending order.
//
// Points with supports of their own (the RKPM windows of a graded fluid mesh, several times
// smaller in a refined capillary than in its feeders) use bins narrower than the largest
// support, each bin searched as deep as the supports that reach into it require
// (search_depths_covering), so that a point among small supports scans its neighbourhood,
// not the largest support's.
#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "kernels/csr_rows.hpp"

namespace rouleau {

struct BinGrid {
  double lower[3];   // [μm]
  double length[3];  // the box's length (the period of a periodic direction) [μm]
  double width[3];   // a bin's width [μm]
  int bins[3];       // per direction
  int periodic[3];   // 1: the direction wraps
  int reach;         // bins searched on each side of a position's own

  KOKKOS_INLINE_FUNCTION int coordinate(const double x, const int d) const {
    const int i = static_cast<int>(floor((x - lower[d]) / width[d]));
    if (periodic[d]) return ((i % bins[d]) + bins[d]) % bins[d];
    return i < 0 ? 0 : (i >= bins[d] ? bins[d] - 1 : i);
  }
  KOKKOS_INLINE_FUNCTION int bin_of(const double x[3]) const {
    return (coordinate(x[2], 2) * bins[1] + coordinate(x[1], 1)) * bins[0] + coordinate(x[0], 0);
  }
  // to − from along d, by the minimum image on a periodic direction.
  KOKKOS_INLINE_FUNCTION double offset(const double to, const double from, const int d) const {
    double y = to - from;
    if (periodic[d]) y -= length[d] * floor(y / length[d] + 0.5);
    return y;
  }
  // visit(bin) for the bins within `reach` of x's (see the file's comment for the order).
  template <class Visit>
  KOKKOS_INLINE_FUNCTION void for_each_bin_near(const double x[3], const Visit& visit) const {
    const int depth[3] = {reach, reach, reach};
    for_each_bin_within(x, depth, visit);
  }
  // visit(bin) for the bins within depth[d] of x's along each direction d, in the same
  // order.
  template <class Visit>
  KOKKOS_INLINE_FUNCTION void for_each_bin_within(const double x[3], const int depth[3], const Visit& visit) const {
    int first[3], last[3];
    bool wraps[3];
    for (int d = 0; d < 3; ++d) {
      const int deep = depth[d];
      wraps[d] = periodic[d] && 2 * deep + 1 <= bins[d];
      if (periodic[d] && !wraps[d]) {  // every bin once
        first[d] = 0;
        last[d] = bins[d] - 1;
      } else {
        const int home = coordinate(x[d], d);
        first[d] = wraps[d] ? home - deep : (home - deep < 0 ? 0 : home - deep);
        last[d] = wraps[d] ? home + deep : (home + deep >= bins[d] ? bins[d] - 1 : home + deep);
      }
    }
    for (int bz = first[2]; bz <= last[2]; ++bz) {
      const int z = wraps[2] ? (bz + bins[2]) % bins[2] : bz;
      for (int by = first[1]; by <= last[1]; ++by) {
        const int y = wraps[1] ? (by + bins[1]) % bins[1] : by;
        for (int bx = first[0]; bx <= last[0]; ++bx) {
          const int xb = wraps[0] ? (bx + bins[0]) % bins[0] : bx;
          visit((z * bins[1] + y) * bins[0] + xb);
        }
      }
    }
  }
  int num_bins() const { return bins[0] * bins[1] * bins[2]; }
};

// Bins that tile the box [lower, upper] exactly, each at least `min_width[d]` wide (one
// bin where the box is narrower), searched `reach` deep. Throws std::invalid_argument on
// an empty box or a width ≤ 0.
inline BinGrid bins_tiling(const double lower[3], const double upper[3], const bool periodic[3],
                           const double min_width[3], const int reach) {
  BinGrid grid{};
  for (int d = 0; d < 3; ++d) {
    grid.lower[d] = lower[d];
    grid.length[d] = upper[d] - lower[d];
    if (!(grid.length[d] > 0.0)) throw std::invalid_argument("rouleau::bins_tiling: an empty box");
    if (!(min_width[d] > 0.0))
      throw std::invalid_argument("rouleau::bins_tiling: the bin width must be > 0, got " +
                                  std::to_string(min_width[d]));
    grid.bins[d] = std::max(1, static_cast<int>(std::floor(grid.length[d] / min_width[d])));
    grid.width[d] = grid.length[d] / grid.bins[d];
    grid.periodic[d] = periodic[d] ? 1 : 0;
  }
  grid.reach = reach;
  return grid;
}

// Cubes of side `width` from `lower`, as many as cover `upper` (at least one per
// direction), not periodic, searched `reach` deep.
inline BinGrid cubic_bins_covering(const double lower[3], const double upper[3], const double width,
                                   const int reach) {
  BinGrid grid{};
  for (int d = 0; d < 3; ++d) {
    grid.lower[d] = lower[d];
    grid.length[d] = upper[d] - lower[d];
    grid.width[d] = width;
    grid.bins[d] = std::max(1, static_cast<int>(std::ceil((upper[d] - lower[d]) / width)));
    grid.periodic[d] = 0;
  }
  grid.reach = reach;
  return grid;
}

// Point indices sorted by (bin, index): the points of bin b are
// points(bin_offsets(b)) … points(bin_offsets(b + 1) − 1).
template <class MemorySpace = Kokkos::DefaultExecutionSpace::memory_space>
struct BinnedPoints {
  BinGrid grid{};
  Kokkos::View<int*, MemorySpace> bin_offsets;  // (num_bins + 1)
  Kokkos::View<int*, MemorySpace> points;       // at least as long as the points binned

  // visit(p) for the binned points p in the bins within the grid's reach of x.
  template <class Visit>
  KOKKOS_INLINE_FUNCTION void for_each_point_near(const double x[3], const Visit& visit) const {
    const auto& offsets = bin_offsets;
    const auto& sorted = points;
    grid.for_each_bin_near(x, [&](const int bin) {
      for (int k = offsets(bin); k < offsets(bin + 1); ++k) visit(sorted(k));
    });
  }
  // visit(p) for the binned points p in the bins within depth(b, d) of x's own bin b along
  // each direction d (depth from search_depths_covering).
  template <class Depths, class Visit>
  KOKKOS_INLINE_FUNCTION void for_each_point_reaching(const double x[3], const Depths& depth,
                                                      const Visit& visit) const {
    const auto& offsets = bin_offsets;
    const auto& sorted = points;
    const int home = grid.bin_of(x);
    const int home_depth[3] = {depth(home, 0), depth(home, 1), depth(home, 2)};
    grid.for_each_bin_within(x, home_depth, [&](const int bin) {
      for (int k = offsets(bin); k < offsets(bin + 1); ++k) visit(sorted(k));
    });
  }
};

// The search depth of each bin, depth(b, d), such that a search from any position x in bin
// b (for_each_point_reaching) visits every binned point p with |x_d − x_pd| < support(p, d)
// along every d (minimum image where periodic; positions outside a walled side are clamped
// into its bins, which only brings them closer). A point in bin c reaches
// r_d = ⌈a_d / w_d⌉ bins to each side of c, a_d the largest support in c; every bin b in that
// span must search at least |b_d − c_d| deep along each d. `support` is (point, 3) on the
// host. A build on the host: Σ_c Π_d (2 r_d + 1) steps over the bins c that hold points.
template <class MemorySpace, class Supports>
Kokkos::View<int* [3], MemorySpace> search_depths_covering(const BinnedPoints<MemorySpace>& binned,
                                                           const Supports& support) {
  const BinGrid& grid = binned.grid;
  const int n_bins = grid.num_bins();
  auto offsets = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), binned.bin_offsets);
  auto sorted = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), binned.points);
  Kokkos::View<int* [3], MemorySpace> depth("rouleau::BinnedPoints::search_depth", n_bins);
  auto host_depth = Kokkos::create_mirror_view(depth);
  Kokkos::deep_copy(host_depth, 0);
  for (int c = 0; c < n_bins; ++c) {
    if (offsets(c) == offsets(c + 1)) continue;
    int span[3];
    for (int d = 0; d < 3; ++d) {
      double largest = 0.0;
      for (int k = offsets(c); k < offsets(c + 1); ++k) largest = std::max(largest, support(sorted(k), d));
      span[d] = static_cast<int>(std::ceil(largest / grid.width[d]));
    }
    const int cell[3] = {c % grid.bins[0], (c / grid.bins[0]) % grid.bins[1], c / (grid.bins[0] * grid.bins[1])};
    for (int kz = -span[2]; kz <= span[2]; ++kz)
      for (int ky = -span[1]; ky <= span[1]; ++ky)
        for (int kx = -span[0]; kx <= span[0]; ++kx) {
          const int k[3] = {kx, ky, kz};
          int b[3];
          bool inside = true;
          for (int d = 0; d < 3; ++d) {
            b[d] = cell[d] + k[d];
            if (grid.periodic[d]) b[d] = ((b[d] % grid.bins[d]) + grid.bins[d]) % grid.bins[d];
            inside = inside && b[d] >= 0 && b[d] < grid.bins[d];
          }
          if (!inside) continue;
          const int bin = (b[2] * grid.bins[1] + b[1]) * grid.bins[0] + b[0];
          for (int d = 0; d < 3; ++d) host_depth(bin, d) = std::max(host_depth(bin, d), std::abs(k[d]));
        }
  }
  Kokkos::deep_copy(depth, host_depth);
  return depth;
}

// min |x − x_p| over the binned points p within `radius` of x, with x_p = position(p, ·)
// (the minimum image on periodic directions), or HUGE_VAL when none is. The bins within the
// grid's reach of x must hold every point within `radius` (bins at least `radius` wide
// searched one deep, say).
template <class MemorySpace, class Positions>
KOKKOS_INLINE_FUNCTION double nearest_distance(const BinnedPoints<MemorySpace>& binned, const Positions& position,
                                               const double x[3], const double radius) {
  double nearest2 = radius * radius;
  bool found = false;
  binned.for_each_point_near(x, [&](const int p) {
    double distance2 = 0.0;
    for (int d = 0; d < 3; ++d) {
      const double offset = binned.grid.offset(position(p, d), x[d], d);
      distance2 += offset * offset;
    }
    if (distance2 <= nearest2) {
      nearest2 = distance2;
      found = true;
    }
  });
  return found ? sqrt(nearest2) : HUGE_VAL;
}

// The `include` of sort_into_bins that takes every point.
struct EveryPoint {
  KOKKOS_INLINE_FUNCTION bool operator()(int) const { return true; }
};

// Sorts the points p < num_points with include(p) into `binned`'s grid, the position of p
// being position(p, d): a counting sort (counts, scan, placement), then each bin's points
// into ascending order. The Views grow when short (a build, not a per-step call).
// Returns how many points were binned.
template <class ExecSpace, class Positions, class Include>
int sort_into_bins(const Positions& position, const int num_points, const Include& include,
                   BinnedPoints<typename ExecSpace::memory_space>& binned) {
  using Offsets = Kokkos::View<int*, typename ExecSpace::memory_space>;
  const BinGrid grid = binned.grid;
  const int n_bins = grid.num_bins();
  if (static_cast<int>(binned.bin_offsets.extent(0)) != n_bins + 1)
    binned.bin_offsets = Offsets("rouleau::BinnedPoints::bin_offsets", n_bins + 1);
  else
    Kokkos::deep_copy(binned.bin_offsets, 0);
  auto offsets = binned.bin_offsets;
  auto bin_of_point = KOKKOS_LAMBDA(const int p) {
    const double x[3] = {position(p, 0), position(p, 1), position(p, 2)};
    return grid.bin_of(x);
  };
  Kokkos::parallel_for(
      "rouleau::BinnedPoints::count", Kokkos::RangePolicy<ExecSpace>(0, num_points), KOKKOS_LAMBDA(const int p) {
        if (include(p)) Kokkos::atomic_add(&offsets(bin_of_point(p)), 1);
      });
  const int total = counts_to_offsets<ExecSpace>("rouleau::BinnedPoints::offsets", offsets, n_bins);
  ensure_length(binned.points, static_cast<std::size_t>(total), "rouleau::BinnedPoints::points");
  auto sorted = binned.points;
  Offsets next("rouleau::BinnedPoints::next", n_bins);
  Kokkos::parallel_for(
      "rouleau::BinnedPoints::place", Kokkos::RangePolicy<ExecSpace>(0, num_points), KOKKOS_LAMBDA(const int p) {
        if (!include(p)) return;
        const int bin = bin_of_point(p);
        sorted(offsets(bin) + Kokkos::atomic_fetch_add(&next(bin), 1)) = p;
      });
  // The placement's order depends on the threads: insertion sort within each bin.
  Kokkos::parallel_for(
      "rouleau::BinnedPoints::order", Kokkos::RangePolicy<ExecSpace>(0, n_bins), KOKKOS_LAMBDA(const int b) {
        for (int k = offsets(b) + 1; k < offsets(b + 1); ++k) {
          const int p = sorted(k);
          int j = k;
          for (; j > offsets(b) && sorted(j - 1) > p; --j) sorted(j) = sorted(j - 1);
          sorted(j) = p;
        }
      });
  return total;
}

}  // namespace rouleau
