#include "solver/block_jacobi.hpp"

#include <cmath>

#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;

// Inverts the 4×4 matrix a (row-major) into inv by Gauss–Jordan with partial pivoting.
KOKKOS_INLINE_FUNCTION bool invert4(double a[4][4], double inv[4][4]) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) inv[i][j] = i == j ? 1.0 : 0.0;
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (fabs(a[r][col]) > fabs(a[pivot][col])) pivot = r;
    if (!(fabs(a[pivot][col]) > 0.0)) return false;
    if (pivot != col)
      for (int j = 0; j < 4; ++j) {
        double t = a[col][j]; a[col][j] = a[pivot][j]; a[pivot][j] = t;
        t = inv[col][j]; inv[col][j] = inv[pivot][j]; inv[pivot][j] = t;
      }
    const double s = 1.0 / a[col][col];
    for (int j = 0; j < 4; ++j) { a[col][j] *= s; inv[col][j] *= s; }
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      const double f = a[r][col];
      for (int j = 0; j < 4; ++j) { a[r][j] -= f * a[col][j]; inv[r][j] -= f * inv[col][j]; }
    }
  }
  return true;
}
}  // namespace

BlockJacobi::BlockJacobi(int num_nodes)
    : num_nodes_(num_nodes), inverse_blocks_("rouleau::BlockJacobi::inverse_blocks", 16 * num_nodes) {}

int BlockJacobi::factor(const Kokkos::View<const double*>& blocks) {
  ProfilingRegion region("rouleau::BlockJacobi::factor");
  auto inverse = inverse_blocks_;
  int singular = 0;
  Kokkos::parallel_reduce(
      "rouleau::BlockJacobi::factor", Kokkos::RangePolicy<ExecSpace>(0, num_nodes_),
      KOKKOS_LAMBDA(const int i, int& count) {
        double a[4][4], inv[4][4];
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c) a[r][c] = blocks(16 * i + 4 * r + c);
        if (!invert4(a, inv)) {
          ++count;
          for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) inv[r][c] = r == c ? 1.0 : 0.0;
        }
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c) inverse(16 * i + 4 * r + c) = inv[r][c];
      },
      singular);
  return singular;
}

void BlockJacobi::apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const {
  auto inverse = inverse_blocks_;
  Kokkos::parallel_for(
      "rouleau::BlockJacobi::apply", Kokkos::RangePolicy<ExecSpace>(0, num_nodes_), KOKKOS_LAMBDA(const int i) {
        double x[4];
        for (int c = 0; c < 4; ++c) x[c] = r(4 * i + c);
        for (int row = 0; row < 4; ++row) {
          double s = 0.0;
          for (int c = 0; c < 4; ++c) s += inverse(16 * i + 4 * row + c) * x[c];
          z(4 * i + row) = s;
        }
      });
}

}  // namespace rouleau
