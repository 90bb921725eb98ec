#pragma once
// Two spheres passing each other on crossing streamlines of a simple shear flow (u = γ̇ y
// e_x): Stokes flow is reversible, so two smooth spheres end on streamlines as far apart
// across the flow as they started (Batchelor & Green 1972); a net change of the offset is
// the discretization's (or roughness's: da Cunha & Hinch 1996) irreversibility. Host-only.
#include "analysis/scene_checks.hpp"

namespace rouleau {

// Cells 0 (starting behind, on the faster streamline) and 1 over a run's rows. The pair's
// trajectory in Stokes flow is symmetric under x₀ − x₁ → −(x₀ − x₁): the offset is read
// where 0 is as far ahead as it started behind (interpolated between rows), not at the
// run's end, where the pair may already be nearing the next periodic image.
struct PairReversibility {
  double initial_offset = 0.0;   // [μm] y₀ − y₁ (centroids), first row, at x₀ − x₁ = −d < 0
  double final_offset = 0.0;     // [μm] the same where x₀ − x₁ first reaches +d
  double asymmetry = 0.0;        // (final − initial offset) / sphere radius
  double smallest_gap = 0.0;     // [μm] least gap_0_1_um up to there
  double symmetric_time = -1.0;  // [s] when x₀ − x₁ reached +d; −1: never (not passed)
  bool passed = false;           // 0 started behind 1 and reached +d
};
// `radius` [μm] of the spheres.
PairReversibility measure_pair_reversibility(const DiagnosticsRows& rows, double radius);

}  // namespace rouleau
