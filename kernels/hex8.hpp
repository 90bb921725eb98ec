#pragma once
// The trilinear 8-node hexahedron on the reference cube [-1,1]³ with the 2×2×2 Gauss
// rule. Node order is VTK/XDMF "Hexahedron": the bottom face (ζ=-1) counter-clockwise
// from (-1,-1), then the top face (ζ=+1) in the same order.
#include <Kokkos_Core.hpp>
#include <cmath>

namespace rouleau {

struct Hex8 {
  static constexpr int nodes = 8;
  static constexpr int quadrature_points = 8;
  static constexpr bool affine = false;  // trilinear: ∂ξ/∂x varies over the element

  // Reference coordinate sign of node a along direction d.
  KOKKOS_INLINE_FUNCTION static double node_sign(int a, int d) {
    // x: - + + - - + + -,  y: - - + + - - + +,  z: - - - - + + + +
    const int bits[3] = {((a + 1) >> 1) & 1, (a >> 1) & 1, (a >> 2) & 1};
    return bits[d] ? 1.0 : -1.0;
  }
  // Gauss point q of the 2×2×2 rule: ξ_d = ±1/√3, weight 1.
  KOKKOS_INLINE_FUNCTION static double point(int q, int d) {
    constexpr double g = 0.57735026918962576451;  // 1/√3
    return ((q >> d) & 1) ? g : -g;
  }
  KOKKOS_INLINE_FUNCTION static double weight(int) { return 1.0; }

  // N_a(ξ) = ⅛ (1 + ξ_a ξ)(1 + η_a η)(1 + ζ_a ζ)
  KOKKOS_INLINE_FUNCTION static double shape(int a, const double xi[3]) {
    return 0.125 * (1.0 + node_sign(a, 0) * xi[0]) * (1.0 + node_sign(a, 1) * xi[1]) *
           (1.0 + node_sign(a, 2) * xi[2]);
  }
  // ∂N_a/∂ξ_d
  KOKKOS_INLINE_FUNCTION static double shape_gradient(int a, int d, const double xi[3]) {
    double g = 0.125 * node_sign(a, d);
    for (int k = 0; k < 3; ++k)
      if (k != d) g *= 1.0 + node_sign(a, k) * xi[k];
    return g;
  }
  KOKKOS_INLINE_FUNCTION static void quadrature_point(int q, double xi[3]) {
    for (int d = 0; d < 3; ++d) xi[d] = point(q, d);
  }
  // The element size h in the stabilization: the edge of the cube of the same volume.
  KOKKOS_INLINE_FUNCTION static double size_from_volume(double volume) { return cbrt(volume); }
};

}  // namespace rouleau
