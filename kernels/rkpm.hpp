#pragma once
// RKPM kernels of the coupling (paper eqs. 15, 16; Liu, Jun & Zhang 1995): the window,
// the shape functions of each solid point over the fluid nodes in its support, and the
// two transfers — interpolation (a pure gather) and spreading (its exact transpose). The
// three are free functions that take the execution space first; coupling/rkpm_coupler
// keeps their buffers and sequences them.
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

#include "kernels/point_bins.hpp"

namespace rouleau {

KOKKOS_INLINE_FUNCTION double cubic_bspline_window(double z) {
  z = fabs(z);
  if (z <= 0.5) return 2.0 / 3.0 - 4.0 * z * z + 4.0 * z * z * z;
  if (z <= 1.0) return 4.0 / 3.0 * (1.0 - z) * (1.0 - z) * (1.0 - z);
  return 0.0;
}

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

// The shape functions of a set of points as CSR rows: row p holds the dof nodes J with
// w_J(x_p) > 0 and Φ_J(x_p). Points with active(p) = 0 (when `active` is not empty) get
// an empty row.
template <class MemorySpace>
struct RkpmSupports {
  BinnedPoints<MemorySpace> node_bins;                      // the dof nodes, binned
  Kokkos::View<const int* [3], MemorySpace> bin_depth;       // search_depths_covering(node_bins, a)
  Kokkos::View<const double* [3], MemorySpace> node_position;  // x_J [μm]
  Kokkos::View<const double* [3], MemorySpace> node_support;   // a_Jd [μm]
};

// One pass over the points (count_only: the rows' lengths into offsets(p); else the rows
// themselves at offsets(p), corrected where they must be, or everywhere with
// `always_correct`). Returns the number of points p with counted(p) (every point when
// `counted` is empty) whose row needed the correction. A singular moment matrix leaves
// NaN in its row.
template <class ExecSpace, class MemorySpace, class Points, class Flags, class Offsets, class Nodes, class Phi>
int rkpm_shape_functions(const ExecSpace& space, const RkpmSupports<MemorySpace>& supports, const Points& points,
                         const Flags& active, const Flags& counted, const bool always_correct, const bool count_only,
                         const Offsets& offsets, const Nodes& nodes, const Phi& phi) {
  const auto node_bins = supports.node_bins;
  const auto bin_depth = supports.bin_depth;
  const BinGrid grid = node_bins.grid;
  const auto node_position = supports.node_position;
  const auto node_support = supports.node_support;
  const bool restricted = active.extent(0) > 0;
  const bool counting_some = counted.extent(0) > 0;
  int corrected = 0;
  Kokkos::parallel_reduce(
      "rouleau::rkpm_shape_functions", Kokkos::RangePolicy<ExecSpace>(space, 0, points.extent(0)),
      KOKKOS_LAMBDA(const int p, int& corrected_count) {
        if (restricted && !active(p)) {  // an empty row
          if (count_only) offsets(p) = 0;
          return;
        }
        const double x[3] = {points(p, 0), points(p, 1), points(p, 2)};
        int count = 0;
        const int first = count_only ? 0 : offsets(p);
        // M = Σ H H^T w with H = (1, y), y = x_J − x
        double m[4][4] = {{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
        node_bins.for_each_point_reaching(x, bin_depth, [&](const int node) {
          double y[3], w = 1.0;
          for (int d = 0; d < 3; ++d) {
            y[d] = grid.offset(node_position(node, d), x[d], d);
            w *= cubic_bspline_window(y[d] / node_support(node, d));
          }
          if (!(w > 0.0)) return;
          if (!count_only) {
            nodes(first + count) = node;
            phi(first + count) = w;
            const double h[4] = {1.0, y[0], y[1], y[2]};
            for (int i = 0; i < 4; ++i)
              for (int j = 0; j < 4; ++j) m[i][j] += h[i] * h[j] * w;
          }
          ++count;
        });
        if (count_only) {
          offsets(p) = count;
          return;
        }
        // Skip the correction where the window alone is a partition of unity with zero
        // first moments (it then reproduces linear fields as it is).
        const double scale = m[0][0] > 0 ? 1.0 : 0.0;
        const double first_moment = fabs(m[0][1]) + fabs(m[0][2]) + fabs(m[0][3]);
        const double support_scale = node_support(nodes(first), 0) + node_support(nodes(first), 1) +
                                     node_support(nodes(first), 2);
        const bool plain_reproduces =
            scale > 0 && fabs(m[0][0] - 1.0) < 1e-12 && first_moment < 1e-12 * support_scale;
        if (plain_reproduces && !always_correct) return;
        double c[4] = {0, 0, 0, 0};
        if (!solve_moment_system(m, c)) {
          for (int k = first; k < first + count; ++k) phi(k) = NAN;
          return;
        }
        // Φ_J = H(0)^T M⁻¹ H(y_J) w_J = (c · H(y_J)) w_J with M c = H(0)
        for (int k = first; k < first + count; ++k) {
          const int node = nodes(k);
          double y[3];
          for (int d = 0; d < 3; ++d) y[d] = grid.offset(node_position(node, d), x[d], d);
          phi(k) *= c[0] + c[1] * y[0] + c[2] * y[1] + c[3] * y[2];
        }
        if (!counting_some || counted(p)) ++corrected_count;
      },
      corrected);
  return corrected;
}

// u(x_p) = Σ_J Φ_J(x_p) u_J: values(p, c) = Σ_k phi(k) nodal(stride · nodes(k) + c) over
// row p, c = 0, 1, 2, for the offsets.extent(0) − 1 rows. One thread per point, a pure
// gather.
template <class ExecSpace, class Offsets, class Nodes, class Phi, class Nodal, class Values>
void rkpm_interpolate(const ExecSpace& space, const Offsets& offsets, const Nodes& nodes, const Phi& phi,
                      const Nodal& nodal, const int stride, const Values& values) {
  Kokkos::parallel_for(
      "rouleau::rkpm_interpolate", Kokkos::RangePolicy<ExecSpace>(space, 0, static_cast<int>(offsets.extent(0)) - 1),
      KOKKOS_LAMBDA(const int p) {
        double u[3] = {0, 0, 0};
        for (int k = offsets(p); k < offsets(p + 1); ++k)
          for (int c = 0; c < 3; ++c) u[c] += phi(k) * nodal(stride * nodes(k) + c);
        for (int c = 0; c < 3; ++c) values(p, c) = u[c];
      });
}

// F_J += Σ_p Φ_J(x_p) F_p, the transpose of rkpm_interpolate: the rows' contributions
// into `scatter` (a ScatterView over the nodal vector, stride per node), which the caller
// resets before and gathers after.
template <class ExecSpace, class Offsets, class Nodes, class Phi, class Forces, class Scatter>
void rkpm_spread(const ExecSpace& space, const Offsets& offsets, const Nodes& nodes, const Phi& phi,
                 const Forces& forces, const Scatter& scatter, const int stride) {
  Kokkos::parallel_for(
      "rouleau::rkpm_spread", Kokkos::RangePolicy<ExecSpace>(space, 0, static_cast<int>(offsets.extent(0)) - 1),
      KOKKOS_LAMBDA(const int p) {
        auto access = scatter.access();
        for (int k = offsets(p); k < offsets(p + 1); ++k)
          for (int c = 0; c < 3; ++c) access(stride * nodes(k) + c) += phi(k) * forces(p, c);
      });
}

}  // namespace rouleau
