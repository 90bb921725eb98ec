#pragma once
// Forward-mode dual numbers: a value and N directional derivatives.
//
// One element routine, templated on its scalar, gives the residual (double), the
// Jacobian action J·δ (Dual<1> seeded with δ) and element matrix columns (Dual<N>
// seeded with unit vectors), so the Jacobian is exact to round-off and never written
// twice by hand. Only the operations the fluid element needs are defined.
#include <Kokkos_Core.hpp>

namespace rouleau {

template <int N>
struct Dual {
  double value;
  double derivative[N];

  KOKKOS_INLINE_FUNCTION Dual() : value(0.0) {
    for (int k = 0; k < N; ++k) derivative[k] = 0.0;
  }
  KOKKOS_INLINE_FUNCTION Dual(double v) : value(v) {  // NOLINT: a constant converts implicitly
    for (int k = 0; k < N; ++k) derivative[k] = 0.0;
  }
  KOKKOS_INLINE_FUNCTION Dual& operator+=(const Dual& b) {
    value += b.value;
    for (int k = 0; k < N; ++k) derivative[k] += b.derivative[k];
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Dual& operator-=(const Dual& b) {
    value -= b.value;
    for (int k = 0; k < N; ++k) derivative[k] -= b.derivative[k];
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Dual& operator*=(double s) {
    value *= s;
    for (int k = 0; k < N; ++k) derivative[k] *= s;
    return *this;
  }
};

template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator+(Dual<N> a, const Dual<N>& b) { return a += b; }
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator-(Dual<N> a, const Dual<N>& b) { return a -= b; }
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator-(Dual<N> a) { return a *= -1.0; }
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator*(Dual<N> a, double s) { return a *= s; }
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator*(double s, Dual<N> a) { return a *= s; }
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator+(Dual<N> a, double s) { a.value += s; return a; }
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator+(double s, Dual<N> a) { a.value += s; return a; }
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator-(Dual<N> a, double s) { a.value -= s; return a; }
// (a + a'ε)(b + b'ε) = ab + (a'b + ab')ε
template <int N>
KOKKOS_INLINE_FUNCTION Dual<N> operator*(const Dual<N>& a, const Dual<N>& b) {
  Dual<N> c(a.value * b.value);
  for (int k = 0; k < N; ++k) c.derivative[k] = a.derivative[k] * b.value + a.value * b.derivative[k];
  return c;
}

// The value part of a scalar, for double and Dual alike.
KOKKOS_INLINE_FUNCTION double value_of(double x) { return x; }
template <int N>
KOKKOS_INLINE_FUNCTION double value_of(const Dual<N>& x) { return x.value; }

}  // namespace rouleau
