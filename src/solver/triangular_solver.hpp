#pragma once
// A sparse triangular solve T x = b by level scheduling: the symbolic phase gives each row
// the level 1 + max(level of the rows it depends on), in one pass over the matrix (O(nnz):
// rows in increasing order for a lower triangle, decreasing for an upper one), and sorts
// the rows by level; the solve launches one parallel kernel per level
// (kernels/triangular_solve.hpp).
//
// It replaces KokkosKernels 3.4's sptrsv, whose symbolic phase rescans every row once per
// level, O(rows × levels): on a box of n³ nodes ILU(0)'s factors have about 12 n levels,
// and the setup of a 3.8e5-unknown multigrid took 98 s, 75 % of it there (bench/scaling.py).
#include <Kokkos_Core.hpp>
#include <cstddef>
#include <vector>

namespace rouleau {

enum class TriangularPart { lower, upper };

class TriangularSolver {
 public:
  // The schedule of the pattern (row_map, entries); every entry of a row must lie on the
  // triangle's side of the diagonal (or on it).
  TriangularSolver(const Kokkos::View<const std::size_t*>& row_map, const Kokkos::View<const int*>& entries,
                   TriangularPart triangle);

  // x = T⁻¹ b with T's values on the pattern; b and x must not alias.
  void solve(const Kokkos::View<const double*>& values, const Kokkos::View<const double*>& b,
             const Kokkos::View<double*>& x) const;

  int num_levels() const { return static_cast<int>(level_offsets_.size()) - 1; }
  // The rows in solve order, level after level, and where each level starts (host).
  const Kokkos::View<const int*>& rows_by_level() const { return rows_by_level_; }
  const std::vector<int>& level_offsets() const { return level_offsets_; }

 private:
  Kokkos::View<const std::size_t*> row_map_;
  Kokkos::View<const int*> entries_;
  Kokkos::View<const int*> rows_by_level_;
  std::vector<int> level_offsets_;
};

}  // namespace rouleau
