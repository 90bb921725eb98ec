#pragma once
// Two spheres passing each other on crossing streamlines of a simple shear flow (u = γ̇ y
// e_x): Stokes flow is reversible, so two smooth spheres end on streamlines as far apart
// across the flow as they started (Batchelor & Green 1972); a net change of the offset is
// the discretization's (or roughness's: da Cunha & Hinch 1996) irreversibility. Host-only.
#include "analysis/scene_checks.hpp"

namespace rouleau {

// Cells 0 (starting behind, on the faster streamline) and 1 over a run's rows.
struct PairReversibility {
  double initial_offset = 0.0;  // [μm] y₀ − y₁ (centroids), first row
  double final_offset = 0.0;    // [μm] the same, last row
  double asymmetry = 0.0;       // (final − initial offset) / sphere radius
  double smallest_gap = 0.0;    // [μm] least gap_0_1_um over the run
  double final_approach = 0.0;  // [μm] x₀ − x₁ at the last row: > 0 once 0 has overtaken 1
  // Passed: 0 ended ahead of 1 by at least `passed_fraction` of the distance it started
  // behind, where the offset is within about 1 % of its far value (the disturbance of a
  // sphere's streamlines decays as the inverse square of the distance).
  static constexpr double passed_fraction = 0.8;
  bool passed = false;
};
// `radius` [μm] of the spheres.
PairReversibility measure_pair_reversibility(const DiagnosticsRows& rows, double radius);

}  // namespace rouleau
