#pragma once
// Incomplete LU factorization without fill, ILU(0), of an assembled CRS matrix, through
// KokkosKernels' spiluk, and the two triangular solves by rouleau's level-scheduled
// TriangularSolver (solver/triangular_solver.hpp says why not KokkosKernels' sptrsv).
// M = L U with the sparsity of A; M⁻¹ r solves L y = r, then U z = y.
#include <Kokkos_Core.hpp>
#include <KokkosKernels_Handle.hpp>
#include <cstddef>
#include <memory>

#include "solver/linear_operator.hpp"
#include "solver/triangular_solver.hpp"

namespace rouleau {

class Ilu0Preconditioner final : public MatrixPreconditioner {
 public:
  using ExecSpace = Kokkos::DefaultExecutionSpace;
  using MemorySpace = ExecSpace::memory_space;
  using Handle = KokkosKernels::Experimental::KokkosKernelsHandle<std::size_t, int, double, ExecSpace, MemorySpace,
                                                                  MemorySpace>;

  // The symbolic factorization on the graph (row_map, entries), done once.
  Ilu0Preconditioner(const Kokkos::View<std::size_t*>& row_map, const Kokkos::View<int*>& entries);
  ~Ilu0Preconditioner() override;
  Ilu0Preconditioner(const Ilu0Preconditioner&) = delete;
  Ilu0Preconditioner& operator=(const Ilu0Preconditioner&) = delete;

  // The numeric factorization of the values on the graph.
  void factor(const Kokkos::View<double*>& values) override;
  using MatrixPreconditioner::factor;  // given a float copy too, ILU(0) factors the double values
  void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const override;
  // Rows in the widest level of the factorization's level schedule: its numeric phase
  // holds a scratch array of that many rows times the matrix's rows (KokkosKernels' spiluk).
  int widest_level() const { return static_cast<int>(factor_handle_.get_spiluk_handle()->get_level_maxrows()); }

 private:
  int num_rows_;
  Kokkos::View<std::size_t*> row_map_, lower_row_map_, upper_row_map_;
  Kokkos::View<int*> entries_, lower_entries_, upper_entries_;
  Kokkos::View<double*> lower_values_, upper_values_, intermediate_;
  std::unique_ptr<TriangularSolver> lower_solver_, upper_solver_;
  mutable Handle factor_handle_;
};

}  // namespace rouleau
