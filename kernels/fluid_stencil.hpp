#pragma once
// The Stokes operator of a uniform box as a stencil (docs/method.md, "The uniform-box stencil").
//
// On a structured box of identical hexahedra in the Stokes limit every element has the
// same matrix, so the assembled operator at a dof node n is a 27-point stencil over the
// offsets o ∈ {−1, 0, 1}³ whose blocks depend only on which of the node's eight
// surrounding elements exist: its class t(n), per direction "on the lower side", "inside"
// (or periodic) or "on the upper side". With δ = (u, p) node by node
//     G_n,ij = Σ_o W[t][o]_j u_i,(n+o)              projected velocity gradient ∂_j u_i
//     (Aδ)_n = Σ_o K[t][o] δ_(n+o)                 Galerkin + PSPG + mass terms (4 × 4 blocks)
//            + e_p Σ_o B[t][o] · G_(n+o)           PSPG's viscous term −τ_M ∇N_a·∇·(G + Gᵀ)
// where K, W and B are sums of one reference element's matrices over the node's
// elements (W = ∫ N_a ∂_j N_b divided by the node's lumped mass; kernels/fluid_element.hpp,
// kernels/fluid_assembly.hpp give the element terms). Only the pressure row sees G in
// the Stokes limit (SUPG has no convective weight there). Each pass is a pure gather:
// one thread per node, no atomics, no per-element geometry, and a fixed summation order.
#include <Kokkos_Core.hpp>

#include "kernels/fluid_assembly.hpp"
#include "kernels/hex8.hpp"

namespace rouleau {

inline constexpr int stencil_node_classes = 27;  // 3 per direction
inline constexpr int stencil_offsets = 27;       // o ∈ {−1, 0, 1}³
// Offset index of o = (ox, oy, oz): (ox + 1) + 3 (oy + 1) + 9 (oz + 1).
KOKKOS_INLINE_FUNCTION constexpr int stencil_offset_index(int ox, int oy, int oz) {
  return (ox + 1) + 3 * (oy + 1) + 9 * (oz + 1);
}

// Dof node numbering of make_box_mesh: node (i, j, k) is i + d_x (j + d_y k), with d the
// number of dof planes per direction (elements in periodic directions, elements + 1 otherwise).
struct StructuredDofNodes {
  int planes[3] = {0, 0, 0};
  int periodic[3] = {0, 0, 0};

  KOKKOS_INLINE_FUNCTION void position(const int n, int (&ijk)[3]) const {
    ijk[0] = n % planes[0];
    ijk[1] = (n / planes[0]) % planes[1];
    ijk[2] = n / (planes[0] * planes[1]);
  }
  // 0 on the lower side, 1 inside (always, in a periodic direction), 2 on the upper side.
  KOKKOS_INLINE_FUNCTION int direction_class(const int d, const int index) const {
    if (periodic[d]) return 1;
    return index == 0 ? 0 : (index == planes[d] - 1 ? 2 : 1);
  }
  KOKKOS_INLINE_FUNCTION int node_class(const int (&ijk)[3]) const {
    return direction_class(0, ijk[0]) + 3 * direction_class(1, ijk[1]) + 9 * direction_class(2, ijk[2]);
  }
  // The node planes ijk_d − 1, ijk_d, ijk_d + 1 of each direction, wrapped in periodic
  // directions and −1 outside the box, each times its stride (x 1, y d_x, z d_x d_y): the
  // neighbour at offset o is plane[0][o_x+1] + plane[1][o_y+1] + plane[2][o_z+1] when no
  // term is negative.
  KOKKOS_INLINE_FUNCTION void neighbor_planes(const int (&ijk)[3], int (&plane)[3][3]) const {
    int stride = 1;
    for (int d = 0; d < 3; ++d) {
      for (int o = 0; o < 3; ++o) {
        int m = ijk[d] + o - 1;
        if (periodic[d])
          m = m < 0 ? m + planes[d] : (m >= planes[d] ? m - planes[d] : m);
        plane[d][o] = (m < 0 || m >= planes[d]) ? -1 : stride * m;
      }
      stride *= planes[d];
    }
  }
  // Calls visit(m, offset) for each neighbour m of the node at ijk inside the box (the node
  // itself included), offset its stencil_offset_index, z slowest and x fastest.
  template <class Visit>
  KOKKOS_INLINE_FUNCTION void for_each_neighbor(const int (&ijk)[3], const Visit& visit) const {
    int plane[3][3];
    neighbor_planes(ijk, plane);
    for (int oz = 0; oz < 3; ++oz) {
      if (plane[2][oz] < 0) continue;
      for (int oy = 0; oy < 3; ++oy) {
        if (plane[1][oy] < 0) continue;
        for (int ox = 0; ox < 3; ++ox)
          if (plane[0][ox] >= 0) visit(plane[0][ox] + plane[1][oy] + plane[2][oz], ox + 3 * oy + 9 * oz);
      }
    }
  }
  // The dof node at ijk + o (wrapped in periodic directions), or −1 outside the box.
  KOKKOS_INLINE_FUNCTION int neighbor(const int (&ijk)[3], const int (&o)[3]) const {
    int index = 0, stride = 1;
    for (int d = 0; d < 3; ++d) {
      int m = ijk[d] + o[d];
      if (periodic[d])
        m = (m + planes[d]) % planes[d];
      else if (m < 0 || m >= planes[d])
        return -1;
      index += stride * m;
      stride *= planes[d];
    }
    return index;
  }
};

// The reference element's linear maps, one column per launch index, from element 0 of a
// uniform box (Stokes limit: the frozen velocity does not enter τ_M):
//   [0, 32)    K(4a+i, 4b+j) = ∂R_(a,i)/∂U_(b,j)                → element_matrix(4b+j, 4a+i)
//   [32, 104)  ∂R_(a,i)/∂G_(b,k)                                → gradient_response(9b+k, 4a+i)
//   [104, 128) ∂(∫ N_a ∂_j u_i)/∂u_(b,m), and the lumped mass   → moment_matrix(3b+m, 9a+3i+j), mass(a)
struct ReferenceElementColumnsFunctor {
  FluidElementData data;
  Kokkos::View<double**> element_matrix, gradient_response, moment_matrix;
  Kokkos::View<double*> mass;

  static constexpr int columns = 32 + 72 + 24;

  KOKKOS_INLINE_FUNCTION void operator()(const int column) const {
    constexpr int n = Hex8::nodes;
    double state[n][4], zero[n][3], gradient[9 * n], residual[n][4];
    for (int a = 0; a < n; ++a) {
      for (int c = 0; c < 4; ++c) state[a][c] = residual[a][c] = 0.0;
      for (int c = 0; c < 3; ++c) zero[a][c] = 0.0;
    }
    for (int k = 0; k < 9 * n; ++k) gradient[k] = 0.0;
    const double h = data.element_size(0);
    if (column < 32) {
      state[column / 4][column % 4] = 1.0;
      fluid_element_residual<Hex8, double>(data.coefficients, data.geometry, 0, h, state, zero, zero, zero, gradient,
                                           residual);
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < 4; ++i) element_matrix(column, 4 * a + i) = residual[a][i];
    } else if (column < 104) {
      gradient[column - 32] = 1.0;
      fluid_element_residual<Hex8, double>(data.coefficients, data.geometry, 0, h, state, zero, zero, zero, gradient,
                                           residual);
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < 4; ++i) gradient_response(column - 32, 4 * a + i) = residual[a][i];
    } else {
      const int b = (column - 104) / 3, m = (column - 104) % 3;
      state[b][m] = 1.0;
      double integral[n][9], element_mass[n];
      element_gradient_moments<Hex8>(data.geometry, 0, state, integral, element_mass);
      for (int a = 0; a < n; ++a)
        for (int k = 0; k < 9; ++k) moment_matrix(column - 104, 9 * a + k) = integral[a][k];
      if (column == 104)
        for (int a = 0; a < n; ++a) mass(a) = element_mass[a];
    }
  }
};

// G_n,ij = Σ_o W[t(n)][o]_j u_i,(n+o):  gradient(9n + 3i + j) ≈ ∂_j u_i at node n.
//   stencil(t, o, j): (Σ_e ∫ N_n ∂_j N_(n+o) dV) / m_n over the class's elements
struct StencilGradientFunctor {
  StructuredDofNodes nodes;
  Kokkos::View<const double***, Kokkos::LayoutRight> stencil;  // [class][offset][3], rows contiguous
  Kokkos::View<const double*> direction;  // δ, 4 per node
  Kokkos::View<double*> gradient;         // G, 9 per node

  KOKKOS_INLINE_FUNCTION void operator()(const int n) const {
    int ijk[3];
    nodes.position(n, ijk);
    const double* weights = &stencil(nodes.node_class(ijk), 0, 0);  // [offset][3]
    double g[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    nodes.for_each_neighbor(ijk, [&](const int m, const int offset) {
      const double* w = weights + 3 * offset;
      const double* u = &direction(4 * m);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) g[3 * i + j] += w[j] * u[i];
    });
    for (int k = 0; k < 9; ++k) gradient(9 * n + k) = g[k];
  }
};

// (Aδ)_n = Σ_o K[t(n)][o] δ_(n+o) + e_p Σ_o B[t(n)][o] · G_(n+o)
//   block_stencil(t, o, 4j + i): the weight of δ_j at n + o in row i of node n (by columns)
//   viscous_stencil(t, o, k):    the weight of G_k at n + o in node n's pressure row
// (no G term when `gradient` is empty: viscous reconstruction off).
struct StencilActionFunctor {
  StructuredDofNodes nodes;
  Kokkos::View<const double***, Kokkos::LayoutRight> block_stencil;    // [class][offset][16], contiguous
  Kokkos::View<const double***, Kokkos::LayoutRight> viscous_stencil;  // [class][offset][9], contiguous
  Kokkos::View<const double*> direction;          // δ, 4 per node
  Kokkos::View<const double*> gradient;           // G(δ), 9 per node, or empty
  Kokkos::View<double*> result;

  KOKKOS_INLINE_FUNCTION void operator()(const int n) const {
    int ijk[3];
    nodes.position(n, ijk);
    const int t = nodes.node_class(ijk);
    const double* blocks = &block_stencil(t, 0, 0);                                       // [offset][16]
    const double* viscous = gradient.extent(0) > 0 ? &viscous_stencil(t, 0, 0) : nullptr;  // [offset][9]
    double r[4] = {0, 0, 0, 0};
    nodes.for_each_neighbor(ijk, [&](const int m, const int offset) {
      const double* w = blocks + 16 * offset;
      const double* d = &direction(4 * m);
      // Column by column: r += column_j δ_j, four contiguous rows.
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) r[i] += w[4 * j + i] * d[j];
      if (viscous) {
        const double* b = viscous + 9 * offset;
        const double* g = &gradient(9 * m);
        for (int k = 0; k < 9; ++k) r[3] += b[k] * g[k];
      }
    });
    for (int i = 0; i < 4; ++i) result(4 * n + i) = r[i];
  }
};

}  // namespace rouleau
