#pragma once
// One level of a level-scheduled sparse triangular solve T x = b (T lower or upper
// triangular, CRS). The rows of a level depend only on rows of earlier levels, so they
// are solved in parallel:
//
//   x_r = (b_r − Σ_{c ≠ r} T_rc x_c) / T_rr   for every row r of the level,
//
// with T_rr = 1 where the row stores no diagonal (a unit triangle, as ILU's L may be).
#include <Kokkos_Core.hpp>
#include <cstddef>

namespace rouleau {

struct TriangularLevelSolve {
  Kokkos::View<const std::size_t*> row_map;
  Kokkos::View<const int*> entries;
  Kokkos::View<const double*> values;
  Kokkos::View<const int*> rows_by_level;  // the rows, level after level
  Kokkos::View<const double*> b;
  Kokkos::View<double*> x;
  int level_begin = 0;  // this level's first position in rows_by_level

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const int row = rows_by_level(level_begin + i);
    double sum = b(row), diagonal = 1.0;
    for (std::size_t k = row_map(row); k < row_map(row + 1); ++k) {
      const int column = entries(k);
      if (column == row)
        diagonal = values(k);
      else
        sum -= values(k) * x(column);
    }
    x(row) = sum / diagonal;
  }
};

}  // namespace rouleau
