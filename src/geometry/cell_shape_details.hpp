#pragma once
// The constructions behind the cell shapes of cell_shapes.hpp, shared by the analytic
// helpers (cell_shapes.cpp) and the mesher (cell_mesh.cpp). Internal to src/geometry.
// Host-only: includes no Kokkos header.
#include <array>
#include <string>
#include <vector>

#include "geometry/cell_geometry.hpp"

namespace rouleau::geometry_detail {

// "cell kind "NAME" (SHAPE BODY)": how errors about a kind name it.
std::string describe_kind(const CellGeometry& kind);

// Throws std::runtime_error naming the kind when its sizes cannot make a body (a size not
// positive or not finite, a shell as thick as the body, a sickle bent onto itself, an RBC
// shell whose inner surface would cross itself or leave no cavity).
void validate_cell_kind(const CellGeometry& kind);

// Gauss–Legendre rule on [−1, 1]: nodes and weights of the n-point rule (exact for
// polynomials of degree 2n − 1).
struct QuadratureRule {
  std::vector<double> nodes, weights;
};
QuadratureRule gauss_legendre(int n);

// ---- RBC: the Evans–Fung profile in the (r, z) half plane, parametrized by an angle.
// With x = r/R = sin θ, θ ∈ [0, π] runs from the top of the axis (θ = 0) over the rim
// (θ = π/2) to the bottom of the axis (θ = π):
//   r(θ) = R sin θ,   z(θ) = R · ½ cos θ (a0 + a1 sin²θ + a2 sin⁴θ),
// which is the profile z = ±R y(r/R) with the square root √(1 − x²) = |cos θ| made smooth.
std::array<double, 2> rbc_profile_point(double theta, double cell_radius);
// d(r, z)/dθ of the same curve.
std::array<double, 2> rbc_profile_tangent(double theta, double cell_radius);
// The outward unit normal of the profile in the (r, z) plane: the tangent turned by +90°,
// n = (−z', r') / |(r', z')| (the curve runs clockwise around the body's cross-section).
std::array<double, 2> rbc_profile_normal(double theta, double cell_radius);

// The inner surface of an RBC shell as a profile: the outer profile moved inward along its
// normal by the shell thickness h, p_inner(θ) = p(θ) − h n(θ), sampled at θ_k = kπ/n,
// k = 0..n (both ends on the axis). Checks that the offset curve is simple (the offset of a
// convex part with curvature radius < h folds back; parts may meet), stays off the axis
// between its ends and leaves a cavity at the axis; throws std::runtime_error naming the
// kind and the reason otherwise.
std::vector<std::array<double, 2>> rbc_inner_profile(const CellGeometry& kind, int intervals);

// ---- Sphere and spheroid: the semi-axes of (x² + y²)/a² + z²/c² = 1, the polar axis along
// the body's z (c = a for a sphere).
struct SpheroidAxes {
  double equatorial, polar;  // a, c [μm]
};
SpheroidAxes spheroid_axes(const CellGeometry& kind);

// ---- Sickle: an ellipsoid bent along a circular arc (see cell_shapes.cpp for the
// construction and why it keeps the volume).
struct SickleBend {
  double semi_length, semi_width, semi_thickness;  // a, b, c of the unbent ellipsoid [μm]
  double arc_radius;                                // ρ [μm]
  double centroid_y;  // Ȳ: y of the enclosed volume's centroid after bending [μm]
};
SickleBend sickle_bend(const CellGeometry& kind);
// The bend map followed by the centroid shift: (x, y, z) of the unbent ellipsoid frame →
// body frame, ((ρ+y) sin(x/ρ), (ρ+y) cos(x/ρ) − ρ − Ȳ, z).
std::array<double, 3> bend_sickle_point(const SickleBend& bend, const std::array<double, 3>& unbent);
// Its inverse (for points within the half plane the body occupies): body frame → unbent.
std::array<double, 3> unbend_sickle_point(const SickleBend& bend, const std::array<double, 3>& body);

}  // namespace rouleau::geometry_detail
