#pragma once
// A multigrid smoother of fully parallel passes: `sweeps` sweeps of damped point-block
// Jacobi on an assembled 4×4-block matrix A (solver/block_matrix_graph.hpp), from z = 0:
//   z_0 = 0,   z_{s+1} = z_s + ω D⁻¹ (r − A z_s),   M⁻¹ r = z_sweeps
// with D the 4×4 diagonal blocks (each node's u, v, w, p). Each sweep is one pass over the
// matrix's rows, node by node (the four rows' residual, then the block product), into a
// second buffer: no triangular solve and no level schedule, so one kernel per sweep
// whatever the mesh.
#include <Kokkos_Core.hpp>

#include "solver/block_jacobi.hpp"
#include "solver/block_matrix_graph.hpp"
#include "solver/linear_operator.hpp"

namespace rouleau {

class BlockJacobiSmoother final : public MatrixPreconditioner {
 public:
  BlockJacobiSmoother(const BlockMatrixGraph& graph, int sweeps, double damping);
  // Inverts A's diagonal blocks and keeps `values` (by reference) for the sweeps.
  void factor(const Kokkos::View<double*>& values) override;
  void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const override;

 private:
  BlockMatrixGraph graph_;
  int sweeps_;
  double damping_;
  Kokkos::View<double*> values_, diagonal_blocks_, other_;
  BlockJacobi inverse_;
};

}  // namespace rouleau
