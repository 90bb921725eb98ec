#include "host_algebra/sparse_direct_solver.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <stdexcept>
#include <string>

namespace rouleau {

struct SparseDirectSolver::Factorization {
  int n = 0;
  std::vector<std::size_t> row_map;
  std::vector<int> columns;
  // Position in matrix.valuePtr() of each CRS entry.
  std::vector<Eigen::Index> position;
  Eigen::SparseMatrix<double> matrix;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
};

SparseDirectSolver::SparseDirectSolver(int n, const std::vector<std::size_t>& row_map,
                                       const std::vector<int>& columns)
    : factorization_(std::make_unique<Factorization>()) {
  Factorization& f = *factorization_;
  f.n = n;
  f.row_map = row_map;
  f.columns = columns;
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(columns.size());
  for (int row = 0; row < n; ++row)
    for (std::size_t k = row_map[row]; k < row_map[row + 1]; ++k) pattern.emplace_back(row, columns[k], 1.0);
  f.matrix.resize(n, n);
  f.matrix.setFromTriplets(pattern.begin(), pattern.end());
  f.matrix.makeCompressed();
  f.position.resize(columns.size());
  for (int row = 0; row < n; ++row)
    for (std::size_t k = row_map[row]; k < row_map[row + 1]; ++k)
      f.position[k] = &f.matrix.coeffRef(row, columns[k]) - f.matrix.valuePtr();
  f.lu.analyzePattern(f.matrix);
}

SparseDirectSolver::~SparseDirectSolver() = default;

void SparseDirectSolver::factor(const std::vector<double>& values) {
  Factorization& f = *factorization_;
  double* stored = f.matrix.valuePtr();
  for (std::size_t k = 0; k < values.size(); ++k) stored[f.position[k]] = values[k];
  f.lu.factorize(f.matrix);
  if (f.lu.info() != Eigen::Success)
    throw std::runtime_error("rouleau::SparseDirectSolver: the LU factorization failed (" + f.lu.lastErrorMessage() +
                             ")");
}

void SparseDirectSolver::solve(const double* b, double* x) const {
  const Factorization& f = *factorization_;
  // Evaluated straight into x (SparseLU copies b into x, then solves in place): no
  // temporary vector per call; the multigrid calls this in every cycle.
  Eigen::Map<Eigen::VectorXd> solution(x, f.n);
  solution = f.lu.solve(Eigen::Map<const Eigen::VectorXd>(b, f.n));
}

}  // namespace rouleau
