// The references of two coupling validations, and the measures that hold a run against
// them, on made-up diagnostics on either side of what they must tell apart:
// - a sphere on the axis of Poiseuille flow in a tube (src/analysis/sphere_in_tube.hpp:
//   Bungay & Brenner 1973 against Faxén's law and the lubrication limit);
// - two spheres passing each other in shear (src/analysis/pair_reversibility.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "analysis/pair_reversibility.hpp"
#include "analysis/sphere_in_tube.hpp"

namespace {

TEST(SphereInTube, SpeedRatioHasTheSmallSphereAndCloseFittingLimits) {
  // λ → 0: Faxén's law on the axis, U = V_max (1 − (2/3) λ²) with V_max = 2 V_mean, the wall
  // corrections starting at O(λ⁵): within 1e-4 at λ = 0.1 (the formula's fit: 1e-6 at 0).
  EXPECT_NEAR(rouleau::sphere_in_tube_speed_ratio(0.0), 2.0, 1e-5);
  EXPECT_NEAR(rouleau::sphere_in_tube_speed_ratio(0.1), 2.0 * (1.0 - 2.0 / 3.0 * 0.01), 1e-4);
  // λ → 1: the lubrication limit 1 + (4/3)(1 − λ) + O((1 − λ)²).
  for (const double lambda : {0.95, 0.98, 0.99}) {
    const double gap = 1.0 - lambda;
    EXPECT_NEAR(rouleau::sphere_in_tube_speed_ratio(lambda), 1.0 + 4.0 / 3.0 * gap, 0.2 * gap * gap + 1e-4)
        << "a/R " << lambda;
  }
  // The values the tube test is judged by; and the ratio falls monotonically with λ.
  EXPECT_NEAR(rouleau::sphere_in_tube_speed_ratio(0.8), 1.276, 5e-4);
  EXPECT_NEAR(rouleau::sphere_in_tube_speed_ratio(0.9), 1.136, 5e-4);
  for (double lambda = 0.0; lambda < 0.99; lambda += 0.01)
    ASSERT_GT(rouleau::sphere_in_tube_speed_ratio(lambda), rouleau::sphere_in_tube_speed_ratio(lambda + 0.01));
  EXPECT_THROW(rouleau::sphere_in_tube_speed_ratio(1.0), std::invalid_argument);
  EXPECT_THROW(rouleau::sphere_in_tube_speed_ratio(-0.1), std::invalid_argument);
}

// Rows every 0.01 s to 0.5 s of cell 0 moving at U, at half that in the first 0.1 s (the
// start-up), with a wobble of amplitude `wobble` μm.
rouleau::DiagnosticsRows plug_rows(double speed, double wobble) {
  rouleau::DiagnosticsRows rows;
  for (int k = 0; k <= 50; ++k) {
    const double t = 0.01 * k;
    const double x = 16.0 + 0.5 * speed * std::min(t, 0.1) + speed * std::max(t - 0.1, 0.0) + wobble * std::sin(40.0 * t);
    rows.push_back({{"time_s", t}, {"cell0_centroid_x_um", x}});
  }
  return rows;
}

TEST(SphereInTube, PlugSpeedIsTheSlopeAfterTheStartUp) {
  const rouleau::PlugSpeed steady = rouleau::measure_plug_speed(plug_rows(12.76, 0.0), 0.1);
  EXPECT_NEAR(steady.speed, 12.76, 1e-9);
  EXPECT_NEAR(steady.speed_spread, 0.0, 1e-9);
  EXPECT_EQ(steady.rows, 41);
  // Including the start-up lowers it: the measure depends on where it starts.
  EXPECT_LT(rouleau::measure_plug_speed(plug_rows(12.76, 0.0), 0.0).speed, 12.7);
  // A wobble shows in the spread, hardly in the slope.
  const rouleau::PlugSpeed wobbly = rouleau::measure_plug_speed(plug_rows(12.76, 0.01), 0.1);
  EXPECT_NEAR(wobbly.speed, 12.76, 0.05);
  EXPECT_GT(wobbly.speed_spread, 0.5);
  EXPECT_THROW(rouleau::measure_plug_speed(plug_rows(12.76, 0.0), 0.49), std::runtime_error);
}

// Two spheres of radius 2 μm, their centres dx = x₀ − x₁ from −14 μm to `end_x` apart
// along the flow and dy = y₀ − y₁ = 2 μm across it at the start: 0 rolls over 1 with a
// gap of 0.2 μm (centres 4.2 μm apart while |dx| < 4.2) and keeps `shift` μm of offset
// after.
rouleau::DiagnosticsRows pair_rows(double shift, double end_x) {
  rouleau::DiagnosticsRows rows;
  for (int k = 0; k <= 100; ++k) {
    const double dx = -14.0 + (end_x + 14.0) * k / 100.0;
    const double far_dy = 2.0 + shift * 0.5 * (1.0 + std::tanh(dx / 2.0));
    const double dy = std::abs(dx) < 4.2 ? std::max(far_dy, std::sqrt(4.2 * 4.2 - dx * dx)) : far_dy;
    const double gap = std::hypot(dx, dy) - 4.0;
    rows.push_back({{"time_s", 0.01 * k},
                    {"cell0_centroid_x_um", 0.5 * dx},
                    {"cell1_centroid_x_um", -0.5 * dx},
                    {"cell0_centroid_y_um", 0.5 * dy},
                    {"cell1_centroid_y_um", -0.5 * dy},
                    {"gap_0_1_um", gap}});
  }
  return rows;
}

TEST(PairReversibility, AsymmetryIsTheOffsetsChangeOverTheRadius) {
  // Reversible: the offset comes back.
  const rouleau::PairReversibility reversible = rouleau::measure_pair_reversibility(pair_rows(0.0, 14.0), 2.0);
  EXPECT_NEAR(reversible.initial_offset, 2.0, 1e-9);
  EXPECT_NEAR(reversible.asymmetry, 0.0, 1e-9);
  EXPECT_TRUE(reversible.passed);
  EXPECT_NEAR(reversible.smallest_gap, 0.2, 1e-9);
  EXPECT_NEAR(reversible.symmetric_time, 1.0, 1e-9);
  // Irreversible: the offset grows by 0.4 μm, a fifth of the radius.
  const rouleau::PairReversibility spread = rouleau::measure_pair_reversibility(pair_rows(0.4, 14.0), 2.0);
  EXPECT_NEAR(spread.asymmetry, 0.2, 1e-5);
  // A run that goes on past the symmetric point, toward the next periodic image, is read
  // at the symmetric point (dx = +14 μm, reached at t = 0.7 s), not at its end.
  const rouleau::PairReversibility longer = rouleau::measure_pair_reversibility(pair_rows(0.4, 26.0), 2.0);
  EXPECT_NEAR(longer.symmetric_time, 0.7, 1e-9);
  EXPECT_NEAR(longer.asymmetry, 0.2, 1e-5);
  // Stopped while still side by side: not passed, and nothing read.
  const rouleau::PairReversibility side_by_side = rouleau::measure_pair_reversibility(pair_rows(0.4, 5.0), 2.0);
  EXPECT_FALSE(side_by_side.passed);
  EXPECT_LT(side_by_side.symmetric_time, 0.0);
}

}  // namespace
