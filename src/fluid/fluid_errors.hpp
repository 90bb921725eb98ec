#pragma once
// L2 errors of a discrete fluid state against an exact solution, by 27-point quadrature
// per element: 3×3×3 Gauss points on a hexahedron (exact to degree 5 per direction); on a
// tetrahedron the same points collapsed onto it (ξ = u(1−v)(1−w), η = v(1−w), ζ = w, with
// the Jacobian (1−v)(1−w)²; exact to degree 3).
// The pressure is compared up to a constant: its mean difference is removed first.
#include <Kokkos_Core.hpp>
#include <cmath>

#include "fluid/fluid_operator.hpp"
#include <type_traits>

#include "fluid/fluid_element_types.hpp"

namespace rouleau {

struct FluidErrors {
  double velocity = 0.0;        // ‖u_h − u‖_L2 (scaled units)
  double pressure = 0.0;        // ‖(p_h − p) − mean(p_h − p)‖_L2
  double velocity_norm = 0.0;   // ‖u‖_L2
  double pressure_norm = 0.0;   // ‖p − mean p‖_L2
};

namespace detail {
// Point q of the 27-point error rule of Element: reference coordinates and weight.
template <class Element>
KOKKOS_INLINE_FUNCTION void error_quadrature_point(int q, double xi[3], double& weight) {
  constexpr double g = 0.77459666924148337704;  // √(3/5)
  const double points[3] = {-g, 0.0, g};
  const double weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const int i = q % 3, j = (q / 3) % 3, k = q / 9;
  if constexpr (std::is_same<Element, Tet4>::value) {
    // Gauss on [0, 1]³: t = (1 + g)/2, weight w/2; then collapsed.
    const double u = 0.5 * (1.0 + points[i]), v = 0.5 * (1.0 + points[j]), w = 0.5 * (1.0 + points[k]);
    xi[0] = u * (1.0 - v) * (1.0 - w);
    xi[1] = v * (1.0 - w);
    xi[2] = w;
    weight = 0.125 * weights[i] * weights[j] * weights[k] * (1.0 - v) * (1.0 - w) * (1.0 - w);
  } else {
    xi[0] = points[i];
    xi[1] = points[j];
    xi[2] = points[k];
    weight = weights[i] * weights[j] * weights[k];
  }
}

// Values at the error-rule point q of element e: scaled position x, discrete u, p, and dV.
template <class Element, class State>
KOKKOS_INLINE_FUNCTION void sample_error_point(const Kokkos::View<const double* [3]>& coordinates,
                                               const Kokkos::View<const int**>& nodes,
                                               const Kokkos::View<const int**>& dof_nodes, const State& state,
                                               double inverse_length, int e, int q, double x[3], double u[3],
                                               double& p, double& dv) {
  double xi[3], weight;
  error_quadrature_point<Element>(q, xi, weight);
  double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int d = 0; d < 3; ++d) x[d] = u[d] = 0.0;
  p = 0.0;
  for (int a = 0; a < Element::nodes; ++a) {
    const double n = Element::shape(a, xi);
    const int geo = nodes(e, a), dof = dof_nodes(e, a);
    for (int d = 0; d < 3; ++d) {
      x[d] += n * coordinates(geo, d) * inverse_length;
      u[d] += n * state(4 * dof + d);
      for (int m = 0; m < 3; ++m) J[d][m] += coordinates(geo, d) * inverse_length * Element::shape_gradient(a, m, xi);
    }
    p += n * state(4 * dof + 3);
  }
  const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                     J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                     J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  dv = det * weight;
}

}  // namespace detail

template <class Element, class Exact>
FluidErrors fluid_l2_errors_on(const FluidOperator& op, const Kokkos::View<const double*>& state, const Exact& exact) {
  const FluidMesh& mesh = op.mesh();
  Kokkos::View<const double* [3]> coordinates = mesh.coordinates;
  Kokkos::View<const int**> nodes = mesh.element_nodes, dof_nodes = mesh.element_dof_nodes;
  const double inverse_length = 1.0 / op.length_scale();
  const int points = 27;
  using Policy = Kokkos::RangePolicy<Kokkos::DefaultExecutionSpace>;

  // Pass 1: mean pressure difference and mean exact pressure.
  double volume = 0.0, mean_difference = 0.0, mean_exact = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::fluid_l2_errors::mean", Policy(0, mesh.num_elements * points),
      KOKKOS_LAMBDA(const int eq, double& vol, double& diff, double& ex) {
        double x[3], u[3], p, dv, ue[3], pe;
        detail::sample_error_point<Element>(coordinates, nodes, dof_nodes, state, inverse_length, eq / points, eq % points, x, u, p,
                              dv);
        exact(x, ue, pe);
        vol += dv;
        diff += (p - pe) * dv;
        ex += pe * dv;
      },
      volume, mean_difference, mean_exact);
  mean_difference /= volume;
  mean_exact /= volume;

  FluidErrors errors;
  Kokkos::parallel_reduce(
      "rouleau::fluid_l2_errors::norms", Policy(0, mesh.num_elements * points),
      KOKKOS_LAMBDA(const int eq, double& eu, double& ep, double& nu, double& np) {
        double x[3], u[3], p, dv, ue[3], pe;
        detail::sample_error_point<Element>(coordinates, nodes, dof_nodes, state, inverse_length, eq / points, eq % points, x, u, p,
                              dv);
        exact(x, ue, pe);
        for (int d = 0; d < 3; ++d) {
          eu += (u[d] - ue[d]) * (u[d] - ue[d]) * dv;
          nu += ue[d] * ue[d] * dv;
        }
        const double dp = (p - pe) - mean_difference;
        ep += dp * dp * dv;
        np += (pe - mean_exact) * (pe - mean_exact) * dv;
      },
      errors.velocity, errors.pressure, errors.velocity_norm, errors.pressure_norm);
  errors.velocity = std::sqrt(errors.velocity);
  errors.pressure = std::sqrt(errors.pressure);
  errors.velocity_norm = std::sqrt(errors.velocity_norm);
  errors.pressure_norm = std::sqrt(errors.pressure_norm);
  return errors;
}

// `exact(x, u, p)` is a device-callable functor giving the exact scaled u, p at scaled x.
template <class Exact>
FluidErrors fluid_l2_errors(const FluidOperator& op, const Kokkos::View<const double*>& state, const Exact& exact) {
  return visit_fluid_element(op.mesh().element_type, [&](auto element) {
    return fluid_l2_errors_on<decltype(element)>(op, state, exact);
  });
}

}  // namespace rouleau
