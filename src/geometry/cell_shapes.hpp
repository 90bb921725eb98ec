#pragma once
// The exact (analytic) shapes of the cell bodies in their body frame, apart from any mesh:
// the Evans–Fung profile, exact volumes and areas, inside tests, and the placement check.
// Host-only: includes no Kokkos header.
#include <array>
#include <vector>

#include "config/case_config.hpp"

namespace rouleau {

// Evans–Fung biconcave profile, paper eq. (1) with a2 negative (the paper's +1.122 is a
// sign slip): at x = r/R ∈ [0, 1], half-thickness z = R · y(x) with
// y(x) = 0.5 (1 − x²)^{1/2} (a0 + a1 x² + a2 x⁴), a0 = 0.207, a1 = 2.002, a2 = −1.122.
double evans_fung_half_thickness(double radius_from_axis, double cell_radius);

// Exact volume [μm³] and outer surface area [μm²] of the body enclosed by the outer
// surface of `kind` (the cavity of a shell included), by quadrature of the exact shape.
double exact_cell_volume(const CellKindConfig& kind);
double exact_cell_area(const CellKindConfig& kind);

// Whether the body-frame point `p` [μm] lies inside the outer surface of `kind`.
bool inside_cell(const CellKindConfig& kind, const std::array<double, 3>& p);

// Points on the outer surface of `kind` in its body frame, about `spacing` apart.
std::vector<std::array<double, 3>> cell_surface_samples(const CellKindConfig& kind, double spacing);

// Rotation matrix R (row-major) of a placement: rotations about the fixed x, then y, then
// z axes by orientation[0..2] degrees, x_world = center + R x_body.
std::array<std::array<double, 3>, 3> placement_rotation(const CellPlacement& placement);

// Checks every cell of `config` before any work: its kind exists, it lies inside the
// fluid domain (every surface point inside the box), and it does not overlap any other
// cell (no surface point of one inside the other). Throws InputError(config.source_file,
// "cells[I].center_um" / "cells[I].kind", reason naming the other cell) on the first fault.
// (A kind whose sizes make no body is reported with the key "cell_kinds.NAME". Surface
// samples 0.15 μm apart: cells 0.3 μm apart pass, overlaps deeper than about 0.01 μm fail.)
void check_cell_placement(const CaseConfig& config);

}  // namespace rouleau
