#pragma once
// The Arnoldi step's orthogonalization for GMRES: classical Gram–Schmidt applied twice
// (CGS2) of a new Krylov vector w against the basis V, in the three fused sweeps of
// kernels/gram_schmidt.hpp (V read three times, the norm on the last sweep).
#include <Kokkos_Core.hpp>

#include "parallel/communicator.hpp"

namespace rouleau {

class GramSchmidt {
 public:
  // For vectors of length n and bases of up to max_columns columns. With a communicator of
  // more than one rank the vectors are each rank's owned entries, and every sum of
  // products is summed over the ranks before it is used (three reductions per call).
  GramSchmidt(long n, int max_columns, const Communicator* communicator = nullptr);

  // w ← w − V h with h = Vᵀw accumulated over two passes (h: host, V.extent(1) entries);
  // returns ‖w‖ after. V's columns must be orthonormal and w must not be one of them.
  double orthogonalize(const Kokkos::View<const double**, Kokkos::LayoutLeft>& V, const Kokkos::View<double*>& w,
                       double* h);

 private:
  Kokkos::View<double**, Kokkos::LayoutRight> partials_;  // (chunk, max_columns + 1)
  // Both passes' coefficients in one View, so that one copy brings them to the host:
  // c1 (and ‖w‖² after it) in [0, max_columns + 1), c2 in [max_columns + 1, 2 max_columns + 2).
  Kokkos::View<double*> coefficients_;
  Kokkos::View<double*>::HostMirror coefficients_host_;
  const Communicator* communicator_;  // null or one rank: nothing to sum over ranks
};

}  // namespace rouleau
