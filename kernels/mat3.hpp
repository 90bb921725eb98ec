#pragma once
// 3×3 matrices in registers for the solid kernels: products, determinant, inverse
// transpose. Row-major: m[i][j] is row i, column j.
#include <Kokkos_Core.hpp>

namespace rouleau {

struct Mat3 {
  double m[3][3];

  KOKKOS_INLINE_FUNCTION static Mat3 zero() {
    Mat3 a{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) a.m[i][j] = 0.0;
    return a;
  }
  KOKKOS_INLINE_FUNCTION static Mat3 identity() {
    Mat3 a = zero();
    for (int i = 0; i < 3; ++i) a.m[i][i] = 1.0;
    return a;
  }
  KOKKOS_INLINE_FUNCTION double operator()(int i, int j) const { return m[i][j]; }
  KOKKOS_INLINE_FUNCTION double& operator()(int i, int j) { return m[i][j]; }
};

KOKKOS_INLINE_FUNCTION double determinant(const Mat3& a) {
  return a.m[0][0] * (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1]) -
         a.m[0][1] * (a.m[1][0] * a.m[2][2] - a.m[1][2] * a.m[2][0]) +
         a.m[0][2] * (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]);
}

// cof(A) = det(A) A⁻ᵀ, the cofactor matrix (defined also for singular A).
KOKKOS_INLINE_FUNCTION Mat3 cofactor(const Mat3& a) {
  Mat3 c;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      c.m[i][j] = a.m[i1][j1] * a.m[i2][j2] - a.m[i1][j2] * a.m[i2][j1];
    }
  return c;
}

KOKKOS_INLINE_FUNCTION Mat3 transpose(const Mat3& a) {
  Mat3 t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) t.m[i][j] = a.m[j][i];
  return t;
}

KOKKOS_INLINE_FUNCTION Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 c = Mat3::zero();
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) c.m[i][j] += a.m[i][k] * b.m[k][j];
  return c;
}

// AᵀA (the right Cauchy–Green tensor C = FᵀF for A = F).
KOKKOS_INLINE_FUNCTION Mat3 transpose_times_self(const Mat3& a) {
  Mat3 c = Mat3::zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c.m[i][j] += a.m[k][i] * a.m[k][j];
  return c;
}

KOKKOS_INLINE_FUNCTION double trace(const Mat3& a) { return a.m[0][0] + a.m[1][1] + a.m[2][2]; }

// A : B = Σ A_ij B_ij
KOKKOS_INLINE_FUNCTION double frobenius_product(const Mat3& a, const Mat3& b) {
  double s = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s += a.m[i][j] * b.m[i][j];
  return s;
}

}  // namespace rouleau
