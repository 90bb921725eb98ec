#pragma once
// The 4-node (linear) tetrahedron: the fluid element of Gmsh vessel meshes (shape
// functions and quadrature, as Hex8), and the solid element in total-Lagrangian form
// (paper eqs. 9–10): its reference data, computed once, and the deformation gradient.
//
// With the reference edge matrix D_m = [X1−X0, X2−X0, X3−X0] (columns), the shape
// functions N1 = ξ, N2 = η, N3 = ζ, N0 = 1 − ξ − η − ζ have the constant gradients
//   ∇_X N_a = D_m⁻ᵀ ∂N_a/∂ξ:  ∇N_1, ∇N_2, ∇N_3 = rows 0, 1, 2 of D_m⁻¹, ∇N_0 = −Σ_{a≥1} ∇N_a,
// the reference volume is V0 = det(D_m)/6, and the deformation gradient is constant:
//   F = Σ_a x_a ⊗ ∇_X N_a = D_s D_m⁻¹,  D_s = [x1−x0, x2−x0, x3−x0].
#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/mat3.hpp"

namespace rouleau {

struct Tet4 {
  static constexpr int nodes = 4;

  // ---- as a fluid element (kernels/fluid_element.hpp), on the reference tetrahedron
  // ξ, η, ζ ≥ 0, ξ + η + ζ ≤ 1 with N0 = 1 − ξ − η − ζ, N1 = ξ, N2 = η, N3 = ζ and the
  // symmetric 4-point rule of degree 2 (Hammer, Marlowe & Stroud 1956): the points
  // (b, b, b), (a, b, b), (b, a, b), (b, b, a) with a = (5 + 3√5)/20, b = (5 − √5)/20,
  // weight 1/24 each (the reference volume is 1/6). Exact for the mass matrix N_a N_b.
  static constexpr int quadrature_points = 4;
  // Affine: ∂ξ/∂x is the same at every point and the weights are equal, so the first
  // point's geometry is the element's and linear fields have closed-form integrals
  // (fluid_element_residual_affine_stokes).
  static constexpr bool affine = true;
  KOKKOS_INLINE_FUNCTION static void quadrature_point(int q, double xi[3]) {
    constexpr double a = 0.58541019662496845446, b = 0.13819660112501051518;
    for (int d = 0; d < 3; ++d) xi[d] = q == d + 1 ? a : b;
  }
  KOKKOS_INLINE_FUNCTION static double weight(int) { return 1.0 / 24.0; }
  KOKKOS_INLINE_FUNCTION static double shape(int a, const double xi[3]) {
    return a == 0 ? 1.0 - xi[0] - xi[1] - xi[2] : xi[a - 1];
  }
  // ∂N_a/∂ξ_d: constant.
  KOKKOS_INLINE_FUNCTION static double shape_gradient(int a, int d, const double*) {
    return a == 0 ? -1.0 : (a == d + 1 ? 1.0 : 0.0);
  }
  // The element size h in the stabilization: the edge of the regular tetrahedron of the
  // same volume, h = (6√2 V)^(1/3) (a cube's edge for the hexahedron, Hex8).
  KOKKOS_INLINE_FUNCTION static double size_from_volume(double volume) {
    return cbrt(8.48528137423857029 * volume);
  }

  // ---- as a solid element (total-Lagrangian)

  // D_m of the points p[a][i] (node a, component i).
  KOKKOS_INLINE_FUNCTION static Mat3 edge_matrix(const double p[4][3]) {
    Mat3 d;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) d.m[i][k] = p[k + 1][i] - p[0][i];
    return d;
  }

  // ∇_X N_a (gradient[a][j] = ∂N_a/∂X_j) from D_m⁻¹.
  KOKKOS_INLINE_FUNCTION static void shape_gradients(const Mat3& inverse_edge_matrix, double gradient[4][3]) {
    for (int j = 0; j < 3; ++j) {
      gradient[0][j] = 0.0;
      for (int a = 1; a < 4; ++a) {
        gradient[a][j] = inverse_edge_matrix.m[a - 1][j];
        gradient[0][j] -= gradient[a][j];
      }
    }
  }

  // F = D_s D_m⁻¹ from the current node positions x[a][i].
  KOKKOS_INLINE_FUNCTION static Mat3 deformation_gradient(const double x[4][3], const Mat3& inverse_edge_matrix) {
    return multiply(edge_matrix(x), inverse_edge_matrix);
  }

  // Element e's current node positions x[a][i] and its D_m⁻¹, gathered from the (node, 3)
  // positions, (element, 4) nodes and (element, 3, 3) D_m⁻¹ Views.
  template <class Positions, class ElementNodes, class InverseEdgeMatrices>
  KOKKOS_INLINE_FUNCTION static void gather(const int e, const Positions& positions, const ElementNodes& element_nodes,
                                            const InverseEdgeMatrices& inverse_edge_matrices, double x[4][3],
                                            Mat3& inverse_edge_matrix) {
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) x[a][i] = positions(element_nodes(e, a), i);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) inverse_edge_matrix.m[i][j] = inverse_edge_matrices(e, i, j);
  }
};

// Reference data of every tetrahedron, computed once from the reference positions:
// D_m⁻¹ per element and V0 = det(D_m)/6. Counts the elements with V0 ≤ 0 (inverted or
// degenerate), which the caller refuses.
template <class NodeView, class ElementView, class InverseView, class VolumeView>
struct Tet4ReferenceFunctor {
  NodeView reference_positions;        // (node, 3)
  ElementView element_nodes;           // (element, 4)
  InverseView inverse_edge_matrix;     // (element, 3, 3): D_m⁻¹
  VolumeView reference_volume;         // (element)

  KOKKOS_INLINE_FUNCTION void operator()(const int e, int& degenerate) const {
    double p[4][3];
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) p[a][i] = reference_positions(element_nodes(e, a), i);
    const Mat3 d = Tet4::edge_matrix(p);
    const double det = determinant(d);
    reference_volume(e) = det / 6.0;
    if (!(det > 0.0)) {
      ++degenerate;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) inverse_edge_matrix(e, i, j) = 0.0;
      return;
    }
    // D_m⁻¹ = cof(D_m)ᵀ / det(D_m)
    const Mat3 c = cofactor(d);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) inverse_edge_matrix(e, i, j) = c.m[j][i] / det;
  }
};

}  // namespace rouleau
