#pragma once
// The Arnoldi step's orthogonalization for GMRES: classical Gram–Schmidt applied twice
// (CGS2) of a new Krylov vector w against the basis V, in the three fused sweeps of
// kernels/gram_schmidt.hpp (V read three times, the norm on the last sweep).
#include <Kokkos_Core.hpp>

namespace rouleau {

class GramSchmidt {
 public:
  // For vectors of length n and bases of up to max_columns columns.
  GramSchmidt(long n, int max_columns);

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
};

}  // namespace rouleau
