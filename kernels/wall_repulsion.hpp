#pragma once
// Short-range repulsion of cell surface nodes from the wall of a vessel (an axisymmetric
// lumen along x, radius R(x)), so that cells are kept from crossing it (docs/vessels.md).
//
// A surface node a at axial position x and distance r from the axis is d = R(x) − r from
// the wall, measured radially (on a wall sloped by θ the normal distance is d cos θ: at
// most 8 % less in the shipped cases). Within the range d0 it carries the energy
//   E_a = p_w A_a d0 s³ / 3,   s = 1 − d/d0  (d < d0; 0 beyond),
// with A_a its reference area weight, so its force is
//   f_a = −∂E_a/∂x_a = p_w A_a s² ∇d,   ∇d = (R'(x), −y/r, −z/r):
// a pressure growing from 0 at d0 to p_w at contact, pushing the node away from the wall
// (and along x where the wall slopes). Conservative: the force is exactly minus the
// gradient of the energy. R and R' are tabulated at equal steps Δ within each part of the
// profile (the parts' junctions, where R'' jumps, are knots) and R interpolated by cubic
// Hermite polynomials (C¹, error O(Δ⁴)), R' as their derivative, so the force stays the
// energy's exact gradient; outside [0, L] the end values hold, R' = 0.
#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/launch_tags.hpp"

namespace rouleau {

struct VesselWallRepulsion {
  static constexpr int max_parts = 5;
  Kokkos::View<const double*> radius_table;  // R at the knots, part after part [μm]
  Kokkos::View<const double*> slope_table;   // R' at the knots
  int parts = 0;
  double part_start[max_parts] = {};         // x where each part starts [μm]
  double part_spacing[max_parts] = {};       // Δ in each part [μm]
  int part_first[max_parts] = {};            // its first knot in the tables
  int part_intervals[max_parts] = {};        // its number of intervals
  double pressure = 0.0;                     // p_w [Pa]
  double range = 0.5;                        // d0 [μm]

  // R(x) and R'(x) from the tables: in the part holding x, with u = (x − x_start)/Δ,
  // k = ⌊u⌋ and t = u − k on [x_k, x_k+1],
  //   R = h00 R_k + h10 Δ R'_k + h01 R_k+1 + h11 Δ R'_k+1,
  //   h00 = 2t³ − 3t² + 1, h10 = t³ − 2t² + t, h01 = −2t³ + 3t², h11 = t³ − t².
  KOKKOS_INLINE_FUNCTION void wall_radius(double x, double& radius, double& slope) const {
    const int last = static_cast<int>(radius_table.extent(0)) - 1;
    if (!(x > part_start[0])) {
      radius = radius_table(0);
      slope = 0.0;
      return;
    }
    int p = 0;
    while (p + 1 < parts && x >= part_start[p + 1]) ++p;
    const double u = (x - part_start[p]) / part_spacing[p];
    if (!(u < part_intervals[p])) {  // beyond the last part
      radius = radius_table(last);
      slope = 0.0;
      return;
    }
    const int k = static_cast<int>(u);
    const double t = u - k, t2 = t * t, t3 = t2 * t, h = part_spacing[p];
    const int knot = part_first[p] + k;
    const double r0 = radius_table(knot), r1 = radius_table(knot + 1);
    const double m0 = h * slope_table(knot), m1 = h * slope_table(knot + 1);
    radius = (2 * t3 - 3 * t2 + 1) * r0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * r1 + (t3 - t2) * m1;
    slope = ((6 * t2 - 6 * t) * r0 + (3 * t2 - 4 * t + 1) * m0 + (-6 * t2 + 6 * t) * r1 + (3 * t2 - 2 * t) * m1) / h;
  }

  // Adds f_a to force and returns E_a for the node at p with area weight w.
  KOKKOS_INLINE_FUNCTION double node_force(const double p[3], double w, double f[3]) const {
    f[0] = f[1] = f[2] = 0.0;
    if (!(w > 0.0)) return 0.0;
    double radius, slope;
    wall_radius(p[0], radius, slope);
    const double r = sqrt(p[1] * p[1] + p[2] * p[2]);
    const double d = radius - r;
    if (!(d < range) || !(r > 0.0)) return 0.0;
    const double s = 1.0 - d / range;
    const double magnitude = pressure * w * s * s;
    // ∇d = (R', −y/r, −z/r)
    f[0] = magnitude * slope;
    f[1] = -magnitude * p[1] / r;
    f[2] = -magnitude * p[2] / r;
    return pressure * w * range * s * s * s / 3.0;
  }
};

// force(a) = f_a (every node; zero away from the wall or off the surface); launched with
// ForcesOnly (parallel_for) or ForcesAndEnergy (parallel_reduce summing E_a).
template <class NodeVectors, class Weights>
struct WallRepulsionFunctor {
  VesselWallRepulsion wall;
  typename NodeVectors::const_type positions;  // [μm]
  Weights area_weights;                        // reference outer-surface area weight per node [μm²], 0 inside
  NodeVectors force;                           // [pN]

  KOKKOS_INLINE_FUNCTION double node(const int n) const {
    const double p[3] = {positions(n, 0), positions(n, 1), positions(n, 2)};
    double f[3];
    const double energy = wall.node_force(p, area_weights(n), f);
    for (int c = 0; c < 3; ++c) force(n, c) = f[c];
    return energy;
  }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesOnly, const int n) const { node(n); }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesAndEnergy, const int n, double& energy) const { energy += node(n); }
};

}  // namespace rouleau
