#pragma once
// The exact (analytic) shapes of the cell bodies in their body frame, apart from any mesh:
// the Evans–Fung profile, exact volumes and areas, inside tests, surface samples, and the
// rotation that places a body in the domain.
// Host-only: includes no Kokkos header.
#include <array>
#include <vector>

#include "geometry/cell_geometry.hpp"

namespace rouleau {

// Evans–Fung biconcave profile, paper eq. (1) with a2 negative (the paper's +1.122 is a
// sign slip): at x = r/R ∈ [0, 1], half-thickness z = R · y(x) with
// y(x) = 0.5 (1 − x²)^{1/2} (a0 + a1 x² + a2 x⁴), a0 = 0.207, a1 = 2.002, a2 = −1.122.
double evans_fung_half_thickness(double radius_from_axis, double cell_radius);

// Exact volume [μm³] and outer surface area [μm²] of the body enclosed by the outer
// surface of `kind` (the cavity of a shell included), by quadrature of the exact shape.
double exact_cell_volume(const CellGeometry& kind);
double exact_cell_area(const CellGeometry& kind);

// Whether the body-frame point `p` [μm] lies inside the outer surface of `kind`.
bool inside_cell(const CellGeometry& kind, const std::array<double, 3>& p);

// Points on the outer surface of `kind` in its body frame, about `spacing` apart.
std::vector<std::array<double, 3>> cell_surface_samples(const CellGeometry& kind, double spacing);

// Rotation matrix R (row-major) of a placed body: rotations about the fixed x, then y, then
// z axes by orientation_deg[0..2] degrees, x_world = center + R x_body.
std::array<std::array<double, 3>, 3> placement_rotation(const std::array<double, 3>& orientation_deg);

}  // namespace rouleau
