#pragma once
// A sparse LU factorization on the host (Eigen's SparseLU with a COLAMD ordering), for the
// coarsest level of the multigrid hierarchy. Host-only: no Kokkos headers, so a CUDA build
// compiles it with the host compiler.
#include <cstddef>
#include <memory>
#include <vector>

namespace rouleau {

class SparseDirectSolver {
 public:
  // The pattern of an n × n CRS matrix, analysed once.
  SparseDirectSolver(int n, const std::vector<std::size_t>& row_map, const std::vector<int>& columns);
  ~SparseDirectSolver();
  SparseDirectSolver(const SparseDirectSolver&) = delete;
  SparseDirectSolver& operator=(const SparseDirectSolver&) = delete;

  // The numeric factorization of `values` on the pattern; throws std::runtime_error with
  // Eigen's reason when the matrix is singular.
  void factor(const std::vector<double>& values);
  // x = A⁻¹ b (x and b may be the same array), n entries each.
  void solve(const double* b, double* x) const;

 private:
  struct Factorization;
  std::unique_ptr<Factorization> factorization_;
};

}  // namespace rouleau
