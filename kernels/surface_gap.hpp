#pragma once
// The gap between two cells' outer surfaces and their contact area (for the paper's
// aggregation scenes). For every surface node of one cell, the distance to the nearest
// surface triangle of the other: the smallest is the gap; the surface (nodal area weights)
// closer than a contact distance is the contact area, seen from that cell.
#include <Kokkos_Core.hpp>
#include <cmath>

namespace rouleau {

// |p − q|² with q the point of triangle (a, b, c) closest to p. The closest point lies in
// one of the triangle's seven Voronoi regions — a vertex, an edge or the face — told
// apart by the signs of the projections of p − a, p − b, p − c on the edges e1 = b − a,
// e2 = c − a, and the barycentric coordinates they give.
KOKKOS_INLINE_FUNCTION double point_triangle_distance_squared(const double p[3], const double a[3],
                                                              const double b[3], const double c[3]) {
  double e1[3], e2[3], ap[3], bp[3], cp[3];
  for (int i = 0; i < 3; ++i) {
    e1[i] = b[i] - a[i];
    e2[i] = c[i] - a[i];
    ap[i] = p[i] - a[i];
    bp[i] = p[i] - b[i];
    cp[i] = p[i] - c[i];
  }
  const auto dot = [](const double u[3], const double v[3]) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const auto distance_squared_to = [&](double s, double t) {  // q = a + s e1 + t e2
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double d = ap[i] - s * e1[i] - t * e2[i];
      d2 += d * d;
    }
    return d2;
  };
  const double d1 = dot(e1, ap), d2 = dot(e2, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return distance_squared_to(0.0, 0.0);  // vertex a
  const double d3 = dot(e1, bp), d4 = dot(e2, bp);
  if (d3 >= 0.0 && d4 <= d3) return distance_squared_to(1.0, 0.0);  // vertex b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return distance_squared_to(d1 / (d1 - d3), 0.0);  // edge ab
  const double d5 = dot(e1, cp), d6 = dot(e2, cp);
  if (d6 >= 0.0 && d5 <= d6) return distance_squared_to(0.0, 1.0);  // vertex c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return distance_squared_to(0.0, d2 / (d2 - d6));  // edge ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {  // edge bc: q = b + w (c − b)
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return distance_squared_to(1.0 - w, w);
  }
  const double inverse = 1.0 / (va + vb + vc);  // the face
  return distance_squared_to(vb * inverse, vc * inverse);
}

// The surface triangles in patches of nearby triangles (a cell's triangles only; a patch q
// holds triangles patch_triangles(s), s in [patch_offsets(q), patch_offsets(q + 1))), each
// bounded by a sphere: centre c = the mean of its triangles' corners, radius ρ = the largest
// corner distance from c. Every point of a patch's triangles lies within ρ of c (a
// triangle lies in the convex hull of its corners), so for a point p the patch's nearest
// point is at least |p − c| − ρ away and its nearest corner at most |p − c| + ρ.
inline constexpr int surface_gap_patch_triangles = 16;  // at most, per patch

template <class NodeVectors, class Triangles>
struct TrianglePatchBoundsFunctor {
  NodeVectors positions;
  Triangles triangles;
  Kokkos::View<const int*> patch_offsets;
  Kokkos::View<const int*> patch_triangles;
  Kokkos::View<double* [4]> patch_bounds;  // (patch, [c_x, c_y, c_z, ρ]), written

  KOKKOS_INLINE_FUNCTION void operator()(const int q) const {
    double centre[3] = {0.0, 0.0, 0.0};
    const int first = patch_offsets(q), last = patch_offsets(q + 1);
    for (int s = first; s < last; ++s)
      for (int v = 0; v < 3; ++v)
        for (int i = 0; i < 3; ++i) centre[i] += positions(triangles(patch_triangles(s), v), i);
    for (int i = 0; i < 3; ++i) centre[i] /= 3.0 * (last - first);
    double radius_squared = 0.0;
    for (int s = first; s < last; ++s)
      for (int v = 0; v < 3; ++v) {
        double r2 = 0.0;
        for (int i = 0; i < 3; ++i) {
          const double d = positions(triangles(patch_triangles(s), v), i) - centre[i];
          r2 += d * d;
        }
        radius_squared = r2 > radius_squared ? r2 : radius_squared;
      }
    for (int i = 0; i < 3; ++i) patch_bounds(q, i) = centre[i];
    patch_bounds(q, 3) = sqrt(radius_squared);
  }
};

// distance(k) = the distance from node first_node + k (a surface node: area weight > 0)
// to the nearest triangle of the patches [first_patch, first_patch + patch_count); +∞ for
// nodes off the surface. Exact, as a loop over every triangle would give, but pruned:
// U = min over patches of (|p − c| + ρ) bounds the answer from above, and only the
// triangles of patches with |p − c| − ρ ≤ min(U, the nearest so far) are visited.
template <class NodeVectors, class Weights, class Triangles, class Distances>
struct NodeToSurfaceDistanceFunctor {
  NodeVectors positions;
  Weights area_weights;
  Triangles triangles;
  Kokkos::View<const int*> patch_offsets;
  Kokkos::View<const int*> patch_triangles;
  Kokkos::View<const double* [4]> patch_bounds;
  int first_node, first_patch, patch_count;
  Distances distance;

  KOKKOS_INLINE_FUNCTION double centre_distance(const double p[3], const int q) const {
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double d = p[i] - patch_bounds(q, i);
      d2 += d * d;
    }
    return sqrt(d2);
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int k) const {
    const int node = first_node + k;
    if (!(area_weights(node) > 0.0)) {
      distance(k) = INFINITY;
      return;
    }
    const double p[3] = {positions(node, 0), positions(node, 1), positions(node, 2)};
    double upper = INFINITY;
    for (int q = first_patch; q < first_patch + patch_count; ++q) {
      const double u = centre_distance(p, q) + patch_bounds(q, 3);
      upper = u < upper ? u : upper;
    }
    // A margin of round-off on the lower bound keeps the pruning exact in floating point.
    const double margin = 1e-12 * (1.0 + upper);
    double nearest = INFINITY;  // squared
    for (int q = first_patch; q < first_patch + patch_count; ++q) {
      const double lower = centre_distance(p, q) - patch_bounds(q, 3) - margin;
      if (lower > upper || (lower > 0.0 && lower * lower > nearest)) continue;
      for (int s = patch_offsets(q); s < patch_offsets(q + 1); ++s) {
        const int t = patch_triangles(s);
        double corner[3][3];
        for (int v = 0; v < 3; ++v)
          for (int i = 0; i < 3; ++i) corner[v][i] = positions(triangles(t, v), i);
        const double d2 = point_triangle_distance_squared(p, corner[0], corner[1], corner[2]);
        nearest = d2 < nearest ? d2 : nearest;
      }
    }
    distance(k) = sqrt(nearest);
  }
};

}  // namespace rouleau
