#pragma once
// How a hollow shell meets the fluid when the fluid cannot resolve its thickness
// (coupling.shell_midsurface): a shell node takes the tangential part of its velocity at
// itself and the normal part at its point on the membrane's mid-surface,
//
//   v_I = (1 − n̂_I n̂_I) v(x_I) + n̂_I n̂_I v(p_I),      p_I = x_I − δ_I n̂_I,
//
// and spreads its force the transpose way: (1 − n̂ n̂) F_I from x_I, n̂ n̂ F_I from p_I, so
// the power the cells put in is still the power they take back.
//   n̂_I = n_I / |n_I|,   n_I = Σ_{t ∋ I} a_t,   a_t = (x1 − x0) × (x2 − x0) / 2
// over the shell's surface triangles (outer surface and cavity wall, both oriented out of
// the solid); δ_I is half the thickness of node I's shell. Nodes of filled bodies, and
// nodes no triangle meets, have n̂_I = 0: they are coupled at x_I alone.
//
// Why: with both surfaces of the shell inside one fluid element, the elastic force that
// resists a change of the layer's thickness spreads into almost nothing, and the
// interpolated velocity's unresolved normal strain rate n̂·∇v·n̂ squeezes the layer
// unresisted (a contraction's cell had an element crushed to 3 % of its volume at the
// throat). The two surfaces of the layer take the same normal velocity, that of their
// mid-surface, so the layer keeps its thickness, while its tangential motion (rotation,
// shear, stretch) is the flow's at each node. δ and n̂ are frozen within a step, as the
// RKPM supports are.
#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/cell_surface.hpp"  // triangle_area_vector

namespace rouleau {

// n_I += a_t for the three nodes of each triangle t (scatter, over triangles).
template <class Scatter>
struct SurfaceNormalSumFunctor {
  Kokkos::View<const double* [3]> positions;  // (node, 3) [μm]
  Kokkos::View<const int* [3]> triangles;     // (triangle, 3), oriented out of the solid
  Scatter normal_sums;                        // (node, 3) [μm²]

  KOKKOS_INLINE_FUNCTION void operator()(const int t) const {
    double y[3][3];
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) y[k][i] = positions(triangles(t, k), i);
    double a[3];
    triangle_area_vector(y, a);
    auto access = normal_sums.access();
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) access(triangles(t, k), i) += a[i];
  }
};

// n̂_I = n_I / |n_I| (0 where n_I = 0 or δ_I = 0) and p_I = x_I − δ_I n̂_I (over nodes);
// `normals` holds n_I on entry and n̂_I on exit.
struct MidsurfacePointsFunctor {
  Kokkos::View<const double* [3]> positions;  // x (node, 3) [μm]
  Kokkos::View<const double*> depth;          // δ (node) [μm]
  Kokkos::View<double* [3]> normals;          // n in, n̂ out (node, 3)
  Kokkos::View<double* [3]> points;           // p (node, 3) [μm]

  KOKKOS_INLINE_FUNCTION void operator()(const int node) const {
    const double n[3] = {normals(node, 0), normals(node, 1), normals(node, 2)};
    const double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double scale = length > 0.0 && depth(node) > 0.0 ? 1.0 / length : 0.0;
    for (int i = 0; i < 3; ++i) {
      normals(node, i) = scale * n[i];
      points(node, i) = positions(node, i) - depth(node) * scale * n[i];
    }
  }
};

// v_I = v(x_I) − n̂_I (n̂_I · (v(x_I) − v(p_I))) (over nodes): `at_nodes` holds v(x) on
// entry and v on exit.
struct ShellVelocityFunctor {
  Kokkos::View<const double* [3]> normals;       // n̂ (node, 3)
  Kokkos::View<const double* [3]> at_midsurface; // v(p) (node, 3)
  Kokkos::View<double* [3]> at_nodes;            // v(x) in, v out (node, 3)

  KOKKOS_INLINE_FUNCTION void operator()(const int node) const {
    double normal_difference = 0.0;
    for (int i = 0; i < 3; ++i) normal_difference += normals(node, i) * (at_nodes(node, i) - at_midsurface(node, i));
    for (int i = 0; i < 3; ++i) at_nodes(node, i) -= normal_difference * normals(node, i);
  }
};

// The transpose: tangential(I) = (1 − n̂ n̂) F_I, normal(I) = n̂ n̂ F_I (over nodes).
struct ShellForceSplitFunctor {
  Kokkos::View<const double* [3]> normals;  // n̂ (node, 3)
  Kokkos::View<const double* [3]> forces;   // F (node, 3) [pN]
  Kokkos::View<double* [3]> tangential;     // (node, 3) [pN]
  Kokkos::View<double* [3]> normal;         // (node, 3) [pN]

  KOKKOS_INLINE_FUNCTION void operator()(const int node) const {
    double normal_force = 0.0;
    for (int i = 0; i < 3; ++i) normal_force += normals(node, i) * forces(node, i);
    for (int i = 0; i < 3; ++i) {
      normal(node, i) = normal_force * normals(node, i);
      tangential(node, i) = forces(node, i) - normal(node, i);
    }
  }
};

}  // namespace rouleau
