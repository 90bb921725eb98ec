#pragma once
// RKPM kernels of the coupling (paper eqs. 15, 16; Liu, Jun & Zhang 1995): the window,
// the shape functions of each solid point over the fluid nodes in its support, and the
// two transfers — interpolation (a pure gather) and spreading (its exact transpose).
//
// Window: tensor-product cubic B-spline w_J(x) = Π_d φ((x_d − x_Jd)/a_Jd), with support
// radius a_Jd (2 element sizes at node J by default) and
//   φ(z) = 2/3 − 4z² + 4|z|³          for |z| ≤ 1/2,
//   φ(z) = 4/3 (1 − |z|)³             for 1/2 < |z| ≤ 1,   0 beyond
// (the cubic B-spline of knot spacing a/2: on a uniform mesh with a = 2h its translates
// sum to 1 and reproduce linear fields, so no correction is needed there).
// Linear reproducing correction: with H(y) = (1, y), y = x_J − x, and the moment matrix
// M(x) = Σ_J H H^T w_J, the shape functions Φ_J(x) = H(0)^T M⁻¹ H(x_J − x) w_J reproduce
// every linear field exactly. Where Σ_J w_J = 1 and Σ_J w_J (x_J − x) = 0 already (to
// round-off), M⁻¹ H(0) = H(0) and the correction changes nothing: it is skipped.
#include <Kokkos_Core.hpp>
#include <cmath>

namespace rouleau {

KOKKOS_INLINE_FUNCTION double cubic_bspline_window(double z) {
  z = fabs(z);
  if (z <= 0.5) return 2.0 / 3.0 - 4.0 * z * z + 4.0 * z * z * z;
  if (z <= 1.0) return 4.0 / 3.0 * (1.0 - z) * (1.0 - z) * (1.0 - z);
  return 0.0;
}

// The fluid nodes' bins (built once, at least as wide as the largest support, so a
// point's support lies in the 3³ bins around its own) and the periodic minimum image.
struct RkpmSupportSearch {
  double lower[3], length[3], bin_size[3];
  int periodic[3], bins[3];

  // x_J − x along d, by the minimum image on periodic directions.
  KOKKOS_INLINE_FUNCTION double offset(double node, double point, int d) const {
    double y = node - point;
    if (periodic[d]) y -= length[d] * floor(y / length[d] + 0.5);
    return y;
  }
  KOKKOS_INLINE_FUNCTION int bin_coordinate(double x, int d) const {
    int i = static_cast<int>(floor((x - lower[d]) / bin_size[d]));
    if (periodic[d]) return ((i % bins[d]) + bins[d]) % bins[d];
    return i < 0 ? 0 : (i >= bins[d] ? bins[d] - 1 : i);
  }
};

// Solves the 4×4 symmetric system M c = e0 by Gaussian elimination with partial
// pivoting in registers; returns false when M is singular.
KOKKOS_INLINE_FUNCTION bool solve_moment_system(double m[4][4], double c[4]) {
  double b[4] = {1.0, 0.0, 0.0, 0.0};
  for (int k = 0; k < 4; ++k) {
    int pivot = k;
    for (int i = k + 1; i < 4; ++i)
      if (fabs(m[i][k]) > fabs(m[pivot][k])) pivot = i;
    if (!(fabs(m[pivot][k]) > 1e-300)) return false;
    if (pivot != k) {
      for (int j = 0; j < 4; ++j) {
        const double t = m[k][j];
        m[k][j] = m[pivot][j];
        m[pivot][j] = t;
      }
      const double t = b[k];
      b[k] = b[pivot];
      b[pivot] = t;
    }
    for (int i = k + 1; i < 4; ++i) {
      const double factor = m[i][k] / m[k][k];
      for (int j = k; j < 4; ++j) m[i][j] -= factor * m[k][j];
      b[i] -= factor * b[k];
    }
  }
  for (int i = 3; i >= 0; --i) {
    double s = b[i];
    for (int j = i + 1; j < 4; ++j) s -= m[i][j] * c[j];
    c[i] = s / m[i][i];
  }
  return true;
}

}  // namespace rouleau
