#pragma once
// Measures of each cell from its closed outer surface (triangles counter-clockwise seen
// from outside), by the divergence theorem, and the nodal area weights of the surface.
//
// With each triangle (x0, x1, x2) measured from a point o of its cell (the cell's first
// node, to keep the sums free of cancellation far from the origin), y_k = x_k − o:
//   enclosed volume  V = Σ_t V_t,                 V_t = y0 · (y1 × y2) / 6
//   first moment     V (c − o) = Σ_t V_t (y0 + y1 + y2) / 4
//   surface area     A = Σ_t A_t,                 A_t = |(y1 − y0) × (y2 − y0)| / 2
// (each term is the signed tetrahedron (o, x0, x1, x2), so the sums are exact for the
// polyhedron, with no assumption on o). Nodal area weights: w_n = Σ_{t ∋ n} A_t / 3.
#include <Kokkos_Core.hpp>
#include <cmath>

namespace rouleau {

// Columns of a cell's surface sums.
enum CellSurfaceSum : int { enclosed_volume = 0, surface_area = 1, first_moment_x = 2, sum_count = 5 };

KOKKOS_INLINE_FUNCTION void triangle_area_vector(const double y[3][3], double n[3]) {
  const double e1[3] = {y[1][0] - y[0][0], y[1][1] - y[0][1], y[1][2] - y[0][2]};
  const double e2[3] = {y[2][0] - y[0][0], y[2][1] - y[0][1], y[2][2] - y[0][2]};
  n[0] = 0.5 * (e1[1] * e2[2] - e1[2] * e2[1]);
  n[1] = 0.5 * (e1[2] * e2[0] - e1[0] * e2[2]);
  n[2] = 0.5 * (e1[0] * e2[1] - e1[1] * e2[0]);
}

// A_t = |(x1 − x0) × (x2 − x0)| / 2 of surface triangle t at `positions`.
template <class Positions, class Triangles>
KOKKOS_INLINE_FUNCTION double triangle_area(const Positions& positions, const Triangles& triangles, const int t) {
  double y[3][3];
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i) y[k][i] = positions(triangles(t, k), i);
  double n[3];
  triangle_area_vector(y, n);
  return sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Per cell: sums(cell, CellSurfaceSum) over its outer-surface triangles.
template <class Scatter>
struct CellSurfaceSumsFunctor {
  Kokkos::View<const double* [3]> positions;   // (node, 3) [μm]
  Kokkos::View<const int* [3]> triangles;      // (triangle, 3)
  Kokkos::View<const int*> triangle_cell;      // (triangle)
  Kokkos::View<const int*> cell_first_node;    // (cell): the point o of each cell
  Scatter sums;                                // (cell, sum_count)

  KOKKOS_INLINE_FUNCTION void operator()(const int t) const {
    const int cell = triangle_cell(t);
    const int origin = cell_first_node(cell);
    double y[3][3];
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) y[k][i] = positions(triangles(t, k), i) - positions(origin, i);
    double n[3];
    triangle_area_vector(y, n);
    // V_t = y0 · (y1 × y2) / 6
    const double volume = (y[0][0] * (y[1][1] * y[2][2] - y[1][2] * y[2][1]) +
                           y[0][1] * (y[1][2] * y[2][0] - y[1][0] * y[2][2]) +
                           y[0][2] * (y[1][0] * y[2][1] - y[1][1] * y[2][0])) /
                          6.0;
    auto access = sums.access();
    access(cell, enclosed_volume) += volume;
    access(cell, surface_area) += sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 3; ++i) access(cell, first_moment_x + i) += volume * (y[0][i] + y[1][i] + y[2][i]) / 4.0;
  }
};

// w_n = Σ_{t ∋ n} A_t / 3 over the surface triangles (node weights in (node)).
template <class Scatter>
struct SurfaceAreaWeightsFunctor {
  Kokkos::View<const double* [3]> positions;
  Kokkos::View<const int* [3]> triangles;
  Scatter weights;  // (node)

  KOKKOS_INLINE_FUNCTION void operator()(const int t) const {
    const double third_of_area = triangle_area(positions, triangles, t) / 3.0;
    auto access = weights.access();
    for (int k = 0; k < 3; ++k) access(triangles(t, k)) += third_of_area;
  }
};

}  // namespace rouleau
