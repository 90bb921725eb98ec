#pragma once
// Element loops of the matrix-free fluid operator: geometry setup, residual, Jacobian
// action, and element Jacobian columns (diagonal blocks for the preconditioner, full
// element matrices for tests). Each gathers nodal values, calls fluid_element_residual()
// with the scalar type its pass needs, and scatters through a ScatterView (duplicated
// on CPU threads, atomic on GPUs).
#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>
#include <type_traits>

#include "kernels/dual.hpp"
#include "kernels/fluid_element.hpp"

namespace rouleau {

// What every element pass reads: connectivity in dof nodes, stored quadrature geometry,
// element size h (scaled), and the coefficients of the equations.
struct FluidElementData {
  Kokkos::View<const int**> element_dof_nodes;
  Kokkos::View<const double***> geometry;  // [e][q][geometry_entries]
  Kokkos::View<const double*> element_size;
  FluidCoefficients coefficients;
};

namespace detail {
// Nodal values c0..c0+count−1 of `field` at element e's nodes; zeros where `field` is empty.
template <class Element, int Count>
KOKKOS_INLINE_FUNCTION void gather_nodal(const Kokkos::View<const double*>& field, const FluidElementData& d,
                                         int e, double (&out)[Element::nodes][Count]) {
  const bool present = field.extent(0) > 0;
  for (int a = 0; a < Element::nodes; ++a) {
    const int base = 4 * d.element_dof_nodes(e, a);
    for (int c = 0; c < Count; ++c) out[a][c] = present ? field(base + c) : 0.0;
  }
}
// Adds values c0..c0+Count−1 per node of element e into the node-interleaved scatter
// target (4 entries per dof node).
template <class Element, int Count, class Scatter>
KOKKOS_INLINE_FUNCTION void scatter_nodal(const Scatter& target, const FluidElementData& d, int e,
                                          const double (&values)[Element::nodes][Count]) {
  auto out = target.access();
  for (int a = 0; a < Element::nodes; ++a) {
    const int base = 4 * d.element_dof_nodes(e, a);
    for (int c = 0; c < Count; ++c) out(base + c) += values[a][c];
  }
}
// The immersed nodal loads b at element e's nodes turned, in place, into the force
// density f_J = b_J / m_J they stand for (m the lumped mass per dof node).
template <class Element>
KOKKOS_INLINE_FUNCTION void to_force_density(const Kokkos::View<const double*>& lumped_mass,
                                             const FluidElementData& d, int e, double (&b)[Element::nodes][3]) {
  for (int a = 0; a < Element::nodes; ++a) {
    const double inverse_mass = 1.0 / lumped_mass(d.element_dof_nodes(e, a));
    for (int i = 0; i < 3; ++i) b[a][i] *= inverse_mass;
  }
}
// The 9 projected gradient entries of each of element e's nodes, as Scalar (zero when
// `gradient` is empty); the derivative part (when Scalar is Dual<1>) from
// `direction_gradient` if it is not empty.
template <class Element, class Scalar>
KOKKOS_INLINE_FUNCTION void gather_gradient(const Kokkos::View<const double*>& gradient,
                                            const Kokkos::View<const double*>& direction_gradient,
                                            const FluidElementData& d, int e, Scalar (&out)[Element::nodes * 9]) {
  const bool present = gradient.extent(0) > 0;
  for (int a = 0; a < Element::nodes; ++a) {
    const int base = 9 * d.element_dof_nodes(e, a);
    for (int k = 0; k < 9; ++k) {
      out[9 * a + k] = Scalar(present ? gradient(base + k) : 0.0);
      if constexpr (!std::is_same<Scalar, double>::value)
        if (direction_gradient.extent(0) > 0) out[9 * a + k].derivative[0] = direction_gradient(base + k);
    }
  }
}
}  // namespace detail

// The element's moments of the velocity gradient and its lumped mass:
//   integral[a][3i + j] = ∫ N_a ∂_j u_i dV,   mass[a] = ∫ N_a dV;
// on an affine element ∇u is constant and both are V/4 times it and V/4.
template <class Element, class GeometryView>
KOKKOS_INLINE_FUNCTION void element_gradient_moments(const GeometryView& geometry, const int e,
                                                     const double (&u)[Element::nodes][4],
                                                     double (&integral)[Element::nodes][9],
                                                     double (&mass)[Element::nodes]) {
  constexpr int n = Element::nodes;
  if constexpr (Element::affine) {
    double grad[n][3], grad_u[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    const double share = affine_element_gradients<Element>(geometry, e, grad) / n;
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) grad_u[i][j] += u[a][i] * grad[a][j];
    for (int a = 0; a < n; ++a) {
      mass[a] = share;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) integral[a][3 * i + j] = share * grad_u[i][j];
    }
    return;
  }
  for (int a = 0; a < n; ++a) {
    mass[a] = 0.0;
    for (int k = 0; k < 9; ++k) integral[a][k] = 0.0;
  }
  for (int q = 0; q < Element::quadrature_points; ++q) {
    double xi[3];
    Element::quadrature_point(q, xi);
    double grad_u[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (int a = 0; a < n; ++a)
      for (int d = 0; d < 3; ++d) {
        const double g = Element::shape_gradient(a, 0, xi) * geometry(e, q, d) +
                         Element::shape_gradient(a, 1, xi) * geometry(e, q, 3 + d) +
                         Element::shape_gradient(a, 2, xi) * geometry(e, q, 6 + d);
        for (int i = 0; i < 3; ++i) grad_u[i][d] += u[a][i] * g;
      }
    const double dv = geometry(e, q, 9);
    for (int a = 0; a < n; ++a) {
      const double w = Element::shape(a, xi) * dv;
      mass[a] += w;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) integral[a][3 * i + j] += w * grad_u[i][j];
    }
  }
}

// Lumped L2 projection of the velocity gradient onto the nodes, first half:
//   out(9·a + 3i + j) += ∫ N_a ∂_j u_i dV,   lumped_mass(a) += ∫ N_a dV (when non-empty).
// Dividing by the lumped mass gives G_a.
template <class Element, class Scatter>
struct FluidGradientProjectionFunctor {
  FluidElementData data;
  Kokkos::View<const double*> state;
  Scatter gradient;
  Scatter lumped_mass;
  bool with_mass;

  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    constexpr int n = Element::nodes;
    double u[n][4];
    detail::gather_nodal<Element, 4>(state, data, e, u);
    double integral[n][9], mass[n];
    element_gradient_moments<Element>(data.geometry, e, u, integral, mass);
    auto out = gradient.access();
    for (int a = 0; a < n; ++a) {
      const int node = data.element_dof_nodes(e, a);
      for (int k = 0; k < 9; ++k) out(9 * node + k) += integral[a][k];
    }
    if (with_mass) {
      auto m = lumped_mass.access();
      for (int a = 0; a < n; ++a) m(data.element_dof_nodes(e, a)) += mass[a];
    }
  }
};

// Geometry at each quadrature point from scaled nodal coordinates:
//   J_dk = Σ_a x_a,d ∂N_a/∂ξ_k,  store (J⁻¹)_kd = ∂ξ_k/∂x_d and det J · w_q;
//   element size h = Element::size_from_volume(Σ_q det J w_q). Counts elements with det J ≤ 0.
template <class Element>
struct FluidGeometryFunctor {
  Kokkos::View<const double* [3]> coordinates;
  Kokkos::View<const int**> element_nodes;
  double inverse_length;
  Kokkos::View<double***> geometry;
  Kokkos::View<double*> element_size;

  KOKKOS_INLINE_FUNCTION void operator()(const int e, int& inverted) const {
    double volume = 0.0;
    for (int q = 0; q < Element::quadrature_points; ++q) {
      double xi[3], J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      Element::quadrature_point(q, xi);
      for (int a = 0; a < Element::nodes; ++a) {
        const int node = element_nodes(e, a);
        for (int k = 0; k < 3; ++k) {
          const double g = Element::shape_gradient(a, k, xi);
          for (int d = 0; d < 3; ++d) J[d][k] += coordinates(node, d) * inverse_length * g;
        }
      }
      const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                         J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
      if (!(det > 0.0)) ++inverted;
      const double s = 1.0 / det;
      // (J⁻¹)_kd = cofactor(J)_dk / det J
      const double inv[3][3] = {
          {(J[1][1] * J[2][2] - J[1][2] * J[2][1]) * s, (J[0][2] * J[2][1] - J[0][1] * J[2][2]) * s,
           (J[0][1] * J[1][2] - J[0][2] * J[1][1]) * s},
          {(J[1][2] * J[2][0] - J[1][0] * J[2][2]) * s, (J[0][0] * J[2][2] - J[0][2] * J[2][0]) * s,
           (J[0][2] * J[1][0] - J[0][0] * J[1][2]) * s},
          {(J[1][0] * J[2][1] - J[1][1] * J[2][0]) * s, (J[0][1] * J[2][0] - J[0][0] * J[2][1]) * s,
           (J[0][0] * J[1][1] - J[0][1] * J[1][0]) * s}};
      for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 3; ++d) geometry(e, q, 3 * k + d) = inv[k][d];
      const double dv = det * Element::weight(q);
      geometry(e, q, 9) = dv;
      volume += dv;
    }
    element_size(e) = Element::size_from_volume(volume);
  }
};

// R += element residuals of `state`, with τ from `frozen`; history/force may be empty.
template <class Element, class Scatter>
struct FluidResidualFunctor {
  FluidElementData data;
  Kokkos::View<const double*> state, frozen, history, force, gradient;
  Scatter residual;

  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    constexpr int n = Element::nodes;
    double u[n][4], uf[n][3], h[n][3], f[n][3], r[n][4];
    detail::gather_nodal<Element, 4>(state, data, e, u);
    detail::gather_nodal<Element, 3>(frozen, data, e, uf);
    detail::gather_nodal<Element, 3>(history, data, e, h);
    detail::gather_nodal<Element, 3>(force, data, e, f);
    for (int a = 0; a < n; ++a)
      for (int c = 0; c < 4; ++c) r[a][c] = 0.0;
    double g[n * 9];
    if (data.coefficients.viscous_reconstruction) detail::gather_gradient<Element, double>(gradient, {}, data, e, g);
    fluid_element_residual<Element, double>(data.coefficients, data.geometry, e, data.element_size(e), u, uf, h, f, g,
                                            r);
    detail::scatter_nodal<Element, 4>(residual, data, e, r);
  }
};

// R += the stabilization's share of the immersed nodal loads (fluid_element_load_stabilization):
// `load` holds b (scaled, node-interleaved like the state, velocity entries read),
// `lumped_mass` m per dof node, `frozen` the velocity for τ. An element none of whose
// nodes carries a load adds nothing and is passed over (cells cover few elements).
template <class Element, class Scatter>
struct FluidLoadStabilizationFunctor {
  FluidElementData data;
  Kokkos::View<const double*> frozen, load, lumped_mass;
  Scatter residual;

  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    constexpr int n = Element::nodes;
    double density[n][3];
    detail::gather_nodal<Element, 3>(load, data, e, density);
    bool loaded = false;
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < 3; ++i) loaded = loaded || density[a][i] != 0.0;
    if (!loaded) return;
    detail::to_force_density<Element>(lumped_mass, data, e, density);
    double uf[n][3], r[n][4];
    detail::gather_nodal<Element, 3>(frozen, data, e, uf);
    for (int a = 0; a < n; ++a)
      for (int c = 0; c < 4; ++c) r[a][c] = 0.0;
    fluid_element_load_stabilization<Element>(data.coefficients, data.geometry, e, data.element_size(e), uf, density,
                                              r);
    detail::scatter_nodal<Element, 4>(residual, data, e, r);
  }
};

// The moments of PSPG's subscale velocity, M_ai = ∫ N_a τ_M r_i dV, r the strong momentum
// residual of `state` (with the sources, and the immersed loads' force density when `load`
// is not empty: FluidLoadStabilizationFunctor). Its lumped projection onto the nodes is
// u'_a = −M_a / m_a. In the variational multiscale reading of SUPG/PSPG the fluid's
// velocity is u_h + u', and the weak continuity equation, ∫ N_a ∇·u_h + τ_M ∇N_a·r = 0,
// says that it is u_h + u', not u_h, whose flux is conserved: where a membrane's force
// makes ∇p large, u' carries part of the flow through the membrane.
template <class Element, class Scatter>
struct FluidSubscaleFunctor {
  FluidElementData data;
  Kokkos::View<const double*> state, history, force, gradient, load, lumped_mass;
  Scatter moments;

  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    constexpr int n = Element::nodes;
    double u[n][4], uf[n][3], h[n][3], f[n][3], r[n][4], m[n][3];
    detail::gather_nodal<Element, 4>(state, data, e, u);
    detail::gather_nodal<Element, 3>(state, data, e, uf);
    detail::gather_nodal<Element, 3>(history, data, e, h);
    detail::gather_nodal<Element, 3>(force, data, e, f);
    for (int a = 0; a < n; ++a) {
      for (int c = 0; c < 4; ++c) r[a][c] = 0.0;
      for (int i = 0; i < 3; ++i) m[a][i] = 0.0;
    }
    double g[n * 9];
    if (data.coefficients.viscous_reconstruction) detail::gather_gradient<Element, double>(gradient, {}, data, e, g);
    fluid_element_residual<Element, double>(data.coefficients, data.geometry, e, data.element_size(e), u, uf, h, f, g,
                                            r, m);
    if (load.extent(0) > 0) {
      double b[n][3];
      detail::gather_nodal<Element, 3>(load, data, e, b);
      detail::to_force_density<Element>(lumped_mass, data, e, b);
      fluid_element_load_stabilization<Element>(data.coefficients, data.geometry, e, data.element_size(e), uf, b, r,
                                                m);
    }
    detail::scatter_nodal<Element, 3>(moments, data, e, m);
  }
};

namespace detail {
// Element e's residual r (and, when `moments` is not null, the subscale moments) at
// U + εδ in dual numbers, τ frozen at U: their derivatives along δ are the Jacobian action
// J(U)δ and the moments' derivative. The sources enter as in the residual.
template <class Element>
KOKKOS_INLINE_FUNCTION void directional_element_residual(
    const FluidElementData& data, const int e, const Kokkos::View<const double*>& state,
    const Kokkos::View<const double*>& direction, const Kokkos::View<const double*>& history,
    const Kokkos::View<const double*>& force, const Kokkos::View<const double*>& gradient,
    const Kokkos::View<const double*>& direction_gradient, Dual<1> (&r)[Element::nodes][4],
    Dual<1> (*moments)[3] = nullptr) {
  constexpr int n = Element::nodes;
  double u[n][4], du[n][4], uf[n][3], h[n][3], f[n][3];
  Dual<1> x[n][4];
  gather_nodal<Element, 4>(state, data, e, u);
  gather_nodal<Element, 4>(direction, data, e, du);
  gather_nodal<Element, 3>(history, data, e, h);
  gather_nodal<Element, 3>(force, data, e, f);
  for (int a = 0; a < n; ++a) {
    for (int c = 0; c < 3; ++c) uf[a][c] = u[a][c];
    for (int c = 0; c < 4; ++c) {
      x[a][c] = Dual<1>(u[a][c]);
      x[a][c].derivative[0] = du[a][c];
      r[a][c] = Dual<1>(0.0);
    }
    if (moments)
      for (int c = 0; c < 3; ++c) moments[a][c] = Dual<1>(0.0);
  }
  Dual<1> g[n * 9];
  if (data.coefficients.viscous_reconstruction) gather_gradient<Element, Dual<1>>(gradient, direction_gradient, data, e, g);
  fluid_element_residual<Element, Dual<1>>(data.coefficients, data.geometry, e, data.element_size(e), x, uf, h, f, g,
                                           r, moments);
}
}  // namespace detail

// The derivative of the subscale moments along a direction δ, with τ frozen at `state`:
// D_ai = d/dε ∫ N_a τ_M r_i(U + εδ) dV, in dual numbers as FluidJacobianActionFunctor
// differentiates the residual; u'_a's derivative is −D_a / m_a. The sources, the immersed
// loads' share and the projected gradient of U do not change with the state along δ (the
// viscous term is linear in the gradient) and drop out: none is read.
template <class Element, class Scatter>
struct FluidSubscaleActionFunctor {
  FluidElementData data;
  Kokkos::View<const double*> state, direction;
  Kokkos::View<const double*> direction_gradient;  // G(δ) (viscous reconstruction)
  Scatter moments;

  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    constexpr int n = Element::nodes;
    Dual<1> r[n][4], m[n][3];
    detail::directional_element_residual<Element>(data, e, state, direction, {}, {}, {}, direction_gradient, r, m);
    auto out = moments.access();
    for (int a = 0; a < n; ++a) {
      const int base = 4 * data.element_dof_nodes(e, a);
      for (int i = 0; i < 3; ++i) out(base + i) += m[a][i].derivative[0];
    }
  }
};

// Y += J(U) δ: the residual evaluated on U + εδ in dual numbers (τ frozen at U). The
// sources matter: the SUPG weight u·∇N_a multiplies the strong residual, which holds them.
template <class Element, class Scatter>
struct FluidJacobianActionFunctor {
  FluidElementData data;
  Kokkos::View<const double*> state, direction, history, force;
  Kokkos::View<const double*> gradient, direction_gradient;  // G(U), G(δ) (viscous reconstruction)
  Scatter action;

  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    constexpr int n = Element::nodes;
    Dual<1> r[n][4];
    detail::directional_element_residual<Element>(data, e, state, direction, history, force, gradient,
                                                  direction_gradient, r);
    auto out = action.access();
    for (int a = 0; a < n; ++a) {
      const int base = 4 * data.element_dof_nodes(e, a);
      for (int c = 0; c < 4; ++c) out(base + c) += r[a][c].derivative[0];
    }
  }
};

// Where element Jacobian blocks go: the node-diagonal blocks (block Jacobi), whole
// element matrices (tests), or the global CRS matrix (assembled preconditioners).
enum class JacobianSink { diagonal_blocks, element_matrices, crs };
// The launch over the elements of one colour (RangePolicy<JacobianColorTag>).
struct JacobianColorTag {};

// Element Jacobian columns ∂R_a/∂U_b (4×4 blocks), node b at a time in Dual<4>, sent to
//   diagonal_blocks:  blocks(16·dof_node + 4i + j) for a = b (scattered)
//   element_matrices: matrices(e, 4a+i, 4b+j)
//   crs:              values at row 4A+i, column 4B+j of the graph, plain adds: the
//                     caller launches one colour of elements at a time (no two share a
//                     dof node, colored_elements()), so the sums have a fixed order and
//                     the matrix is the same on every run and thread count
// The projected gradient G couples beyond the element: here it is held at its value
// (for preconditioners), so these are exact only without viscous reconstruction.
template <class Element, JacobianSink Sink, class Scatter>
struct FluidElementJacobianFunctor {
  FluidElementData data;
  Kokkos::View<const double*> state, history, force, gradient;
  Scatter blocks;                                  // diagonal_blocks
  Kokkos::View<double***> matrices;                // element_matrices
  Kokkos::View<const std::size_t*> row_map;        // crs
  Kokkos::View<const int*> node_offsets, node_neighbors;
  Kokkos::View<double*> values;

  // Index k of node B among the neighbors of node A (binary search).
  KOKKOS_INLINE_FUNCTION int neighbor_index(int A, int B) const {
    int lo = node_offsets(A), hi = node_offsets(A + 1) - 1;
    while (lo < hi) {
      const int mid = (lo + hi) / 2;
      if (node_neighbors(mid) < B) lo = mid + 1; else hi = mid;
    }
    return lo - node_offsets(A);
  }

  Kokkos::View<const int*> elements;               // crs: the elements of one colour

  // crs: the i-th element of the colour being assembled.
  KOKKOS_INLINE_FUNCTION void operator()(JacobianColorTag, const int i) const { (*this)(elements(i)); }

  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    constexpr int n = Element::nodes;
    double u[n][4], uf[n][3], h[n][3], f[n][3];
    detail::gather_nodal<Element, 4>(state, data, e, u);
    detail::gather_nodal<Element, 3>(history, data, e, h);
    detail::gather_nodal<Element, 3>(force, data, e, f);
    for (int a = 0; a < n; ++a)
      for (int c = 0; c < 3; ++c) uf[a][c] = u[a][c];
    Dual<4> g[n * 9];
    if (data.coefficients.viscous_reconstruction) detail::gather_gradient<Element, Dual<4>>(gradient, {}, data, e, g);
    for (int b = 0; b < n; ++b) {
      Dual<4> x[n][4], r[n][4];
      for (int a = 0; a < n; ++a)
        for (int c = 0; c < 4; ++c) {
          x[a][c] = Dual<4>(u[a][c]);
          if (a == b) x[a][c].derivative[c] = 1.0;
        }
      fluid_element_residual<Element, Dual<4>>(data.coefficients, data.geometry, e, data.element_size(e), x, uf, h, f,
                                               g, r);
      if constexpr (Sink == JacobianSink::diagonal_blocks) {
        auto out = blocks.access();
        const int base = 16 * data.element_dof_nodes(e, b);
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) out(base + 4 * i + j) += r[b][i].derivative[j];
      } else if constexpr (Sink == JacobianSink::element_matrices) {
        for (int a = 0; a < n; ++a)
          for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) matrices(e, 4 * a + i, 4 * b + j) = r[a][i].derivative[j];
      } else {
        const int B = data.element_dof_nodes(e, b);
        for (int a = 0; a < n; ++a) {
          const int A = data.element_dof_nodes(e, a);
          const int k = neighbor_index(A, B);
          for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
              values(row_map(4 * A + i) + 4 * k + j) += r[a][i].derivative[j];
        }
      }
    }
  }
};

}  // namespace rouleau
