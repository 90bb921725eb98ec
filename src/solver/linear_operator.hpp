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

// A preconditioner made from an assembled matrix's values (on a graph it was built for):
// factor() once per matrix, then apply() any number of times. The multigrid's smoothers.
class MatrixPreconditioner : public Preconditioner {
 public:
  virtual void factor(const Kokkos::View<double*>& values) = 0;
  // The same, given also the matrix rounded to float: a smoother that sweeps in single
  // precision reads `rounded_values` in its sweeps; by default only `values` is used.
  virtual void factor(const Kokkos::View<double*>& values, const Kokkos::View<const float*>& rounded_values) {
    (void)rounded_values;
    factor(values);
  }
};

// M = I.
class IdentityPreconditioner final : public Preconditioner {
 public:
  void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const override {
    Kokkos::deep_copy(z, r);
  }
};

}  // namespace rouleau
