#pragma once
// Interfaces of the Krylov solver: an operator y = A x and a preconditioner z = M⁻¹ r,
// both applied to device Views.
#include <Kokkos_Core.hpp>

namespace rouleau {

class LinearOperator {
 public:
  virtual ~LinearOperator() = default;
  virtual void apply(const Kokkos::View<const double*>& x, const Kokkos::View<double*>& y) const = 0;
};

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  virtual void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const = 0;
};

// M = I.
class IdentityPreconditioner final : public Preconditioner {
 public:
  void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const override {
    Kokkos::deep_copy(z, r);
  }
};

}  // namespace rouleau
