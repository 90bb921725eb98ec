#pragma once
// Point-block Jacobi: M = blockdiag(D_1, ..., D_n) with D_i the 4×4 block of the
// Jacobian that couples the velocity and pressure of node i; M⁻¹ is applied node by node.
#include <Kokkos_Core.hpp>

#include "solver/linear_operator.hpp"

namespace rouleau {

class BlockJacobi final : public Preconditioner {
 public:
  explicit BlockJacobi(int num_nodes);
  // blocks(16·i + 4r + c) = D_i(r, c); inverts every block (Gauss–Jordan, partial pivoting).
  // Returns the number of blocks that were singular (those are replaced by identity).
  int factor(const Kokkos::View<const double*>& blocks);
  void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const override;
  // inverse_blocks()(16·i + 4r + c) = D_i⁻¹(r, c), after factor().
  const Kokkos::View<double*>& inverse_blocks() const { return inverse_blocks_; }

 private:
  int num_nodes_;
  Kokkos::View<double*> inverse_blocks_;
};

}  // namespace rouleau
