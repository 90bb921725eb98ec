#include "solver/triangular_solver.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "kernels/triangular_solve.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

TriangularSolver::TriangularSolver(const Kokkos::View<const std::size_t*>& row_map,
                                   const Kokkos::View<const int*>& entries, TriangularPart triangle)
    : row_map_(row_map), entries_(entries) {
  ProfilingRegion region("rouleau::TriangularSolver::schedule");
  const auto rows = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), row_map);
  const auto columns = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), entries);
  const int n = static_cast<int>(rows.extent(0)) - 1;
  // level(r) = 1 + max level(c) over the rows c ≠ r that row r reads (levels from 0).
  std::vector<int> level(n, 0);
  int num_levels = n > 0 ? 1 : 0;
  for (int step = 0; step < n; ++step) {
    const int row = triangle == TriangularPart::lower ? step : n - 1 - step;
    int row_level = 0;
    for (std::size_t k = rows(row); k < rows(row + 1); ++k) {
      const int column = columns(k);
      if (column == row) continue;
      if (triangle == TriangularPart::lower ? column > row : column < row)
        throw std::invalid_argument("rouleau::TriangularSolver: row " + std::to_string(row) + " has column " +
                                    std::to_string(column) + " on the wrong side of the diagonal");
      row_level = std::max(row_level, level[column] + 1);
    }
    level[row] = row_level;
    num_levels = std::max(num_levels, row_level + 1);
  }
  // Counting sort of the rows by level, ascending row order within a level.
  level_offsets_.assign(num_levels + 1, 0);
  for (int row = 0; row < n; ++row) ++level_offsets_[level[row] + 1];
  for (int l = 0; l < num_levels; ++l) level_offsets_[l + 1] += level_offsets_[l];
  Kokkos::View<int*> sorted("rouleau::TriangularSolver::rows_by_level", n);
  auto sorted_host = Kokkos::create_mirror_view(sorted);
  std::vector<int> next(level_offsets_.begin(), level_offsets_.end() - 1);
  for (int row = 0; row < n; ++row) sorted_host(next[level[row]]++) = row;
  Kokkos::deep_copy(sorted, sorted_host);
  rows_by_level_ = sorted;
}

void TriangularSolver::solve(const Kokkos::View<const double*>& values, const Kokkos::View<const double*>& b,
                             const Kokkos::View<double*>& x) const {
  TriangularLevelSolve level_solve{row_map_, entries_, values, rows_by_level_, b, x};
  for (int l = 0; l < num_levels(); ++l) {
    level_solve.level_begin = level_offsets_[l];
    Kokkos::parallel_for("rouleau::TriangularSolver::level",
                         Kokkos::RangePolicy<>(0, level_offsets_[l + 1] - level_offsets_[l]), level_solve);
  }
}

}  // namespace rouleau
