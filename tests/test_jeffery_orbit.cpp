// Jeffery's orbit (src/analysis/jeffery_orbit.hpp): the closed form against its own
// differential equation, the inclination → symmetry-axis conversion on made-up rows, and
// the comparison on made-up runs on either side of its thresholds (Jeffery 1922).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "analysis/jeffery_orbit.hpp"

namespace {

constexpr double pi = 3.14159265358979323846;

// dφ/dt = γ̇ (r² cos²φ + sin²φ) / (r² + 1).
double jeffery_rate(double angle, double axis_ratio, double shear_rate) {
  const double c = std::cos(angle), s = std::sin(angle), r2 = axis_ratio * axis_ratio;
  return shear_rate * (r2 * c * c + s * s) / (r2 + 1.0);
}

TEST(JefferyOrbit, ClosedFormSolvesJefferysEquationAndTurnsByPiInHalfAPeriod) {
  const double shear_rate = 10.0;
  for (const double r : {0.25, 1.0 / 3.0, 1.0, 3.0, 4.0})
    for (const double start : {0.0, 0.7, 2.0, -1.2}) {
      const double period = rouleau::jeffery_period(r, shear_rate);
      EXPECT_NEAR(period, 2.0 * pi * (r + 1.0 / r) / shear_rate, 1e-14);
      EXPECT_NEAR(rouleau::jeffery_angle(0.0, r, shear_rate, start), start, 1e-12);
      EXPECT_NEAR(rouleau::jeffery_angle(0.5 * period, r, shear_rate, start), start + pi, 1e-9);
      EXPECT_NEAR(rouleau::jeffery_angle(period, r, shear_rate, start), start + 2.0 * pi, 1e-9);
      // Central differences of the closed form over two periods: the equation, and no jump.
      const double dt = 1e-6 * period;
      double previous = start;
      for (int k = 1; k <= 400; ++k) {
        const double t = 2.0 * period * k / 400;
        const double angle = rouleau::jeffery_angle(t, r, shear_rate, start);
        const double rate = (rouleau::jeffery_angle(t + dt, r, shear_rate, start) -
                             rouleau::jeffery_angle(t - dt, r, shear_rate, start)) / (2.0 * dt);
        ASSERT_NEAR(rate, jeffery_rate(angle, r, shear_rate), 1e-5 * shear_rate) << "r " << r << " t " << t;
        ASSERT_GT(angle, previous) << "r " << r << " t " << t;
        ASSERT_LT(angle - previous, 0.2) << "r " << r << " t " << t;
        previous = angle;
      }
    }
}

// The inclination θ (the cross-section's major axis from x, in (−90°, 90°]) of a body whose
// symmetry axis is at φ: a disc's major axis lies across p (θ = −φ), a rod's along it
// (θ = π/2 − φ), both modulo π.
double inclination_deg(double angle, double axis_ratio) {
  const double theta = axis_ratio < 1.0 ? -angle : 0.5 * pi - angle;
  double degrees = std::remainder(theta, pi) * 180.0 / pi;
  if (degrees <= -90.0) degrees += 180.0;
  return degrees;
}

TEST(JefferyOrbit, SymmetryAxisFromInclinationsThroughSeveralHalfTurns) {
  for (const double r : {1.0 / 3.0, 3.0}) {
    std::vector<double> inclinations, angles;
    for (int k = 0; k <= 200; ++k) {
      angles.push_back(0.3 + 4.0 * pi * k / 200);  // two turns, 3.6° per row
      inclinations.push_back(inclination_deg(angles.back(), r));
    }
    const std::vector<double> recovered = rouleau::symmetry_axis_angles(inclinations, r);
    ASSERT_EQ(recovered.size(), angles.size());
    // Up to one multiple of π (the axis has no sign): the same offset for every row.
    const double offset = recovered.front() - angles.front();
    EXPECT_NEAR(std::remainder(offset, pi), 0.0, 1e-12);
    for (std::size_t k = 0; k < angles.size(); ++k) ASSERT_NEAR(recovered[k] - angles[k], offset, 1e-12) << k;
  }
}

// Rows every `step` s to `end` of a body turning by Jeffery's law for axis ratio
// `body_ratio`, as the run's inclination would give them.
struct Rows {
  std::vector<double> times, angles;
};
Rows jeffery_rows(double body_ratio, double shear_rate, double start, double end, double step) {
  Rows rows;
  for (double t = 0.0; t <= end + 1e-12; t += step) {
    rows.times.push_back(t);
    rows.angles.push_back(rouleau::jeffery_angle(t, body_ratio, shear_rate, start));
  }
  return rows;
}

TEST(JefferyOrbit, ComparisonPassesJefferysOwnOrbitAndFailsAFatterBody) {
  const double r = 1.0 / 3.0, shear_rate = 10.0, period = rouleau::jeffery_period(r, shear_rate);
  // Jeffery's own orbit, sampled as a run would be (every 0.01 s past the half turn).
  const Rows exact = jeffery_rows(r, shear_rate, 0.0, 0.6 * period, 0.01);
  const rouleau::JefferyComparison same = rouleau::compare_with_jeffery(exact.times, exact.angles, r, shear_rate);
  EXPECT_LT(same.rms_angle_error_deg, 1e-9);
  EXPECT_NEAR(same.measured_period, period, 1e-3 * period);  // the half turn interpolated between rows
  EXPECT_TRUE(same.met());
  // The flip from 45° to 135°: Jeffery's closed form, and the orbit's own crossing times.
  const double omega = shear_rate * r / (r * r + 1.0);
  EXPECT_NEAR(same.jeffery_flip_time, (pi - 2.0 * std::atan(3.0)) / omega, 1e-12);
  EXPECT_NEAR(same.flip_time, same.jeffery_flip_time, 2e-4);  // interpolated between rows 0.01 s apart
  // What a coarse fluid mesh makes of this disc: it turns like a thicker one (c/a = 1/2,
  // as measured at h_f = 1 μm): period −25 %, the angle up to 50° ahead.
  const Rows fat = jeffery_rows(0.5, shear_rate, 0.0, 0.6 * period, 0.01);
  const rouleau::JefferyComparison thick = rouleau::compare_with_jeffery(fat.times, fat.angles, r, shear_rate);
  EXPECT_NEAR(thick.period_error, rouleau::jeffery_period(0.5, shear_rate) / period - 1.0, 2e-3);
  EXPECT_GT(thick.rms_angle_error_deg, 10.0);
  EXPECT_FALSE(thick.met());
  // A thicker disc flips more slowly where it is fastest: (π − 2 atan 2)/ω' against (π − 2 atan 3)/ω.
  const double thick_omega = shear_rate * 0.5 / 1.25;
  EXPECT_NEAR(thick.flip_time, (pi - 2.0 * std::atan(2.0)) / thick_omega, 2e-4);
  // Just inside and outside the period's 5 %: a disc of c/a = 0.345 (period −3.4 %) passes
  // on the period, one of 0.36 (−7.3 %) does not.
  const Rows near = jeffery_rows(0.345, shear_rate, 0.0, 0.6 * period, 0.01);
  const Rows beyond = jeffery_rows(0.36, shear_rate, 0.0, 0.6 * period, 0.01);
  EXPECT_LT(std::abs(rouleau::compare_with_jeffery(near.times, near.angles, r, shear_rate).period_error), 0.05);
  EXPECT_FALSE(rouleau::compare_with_jeffery(beyond.times, beyond.angles, r, shear_rate).met());
  // A run that ends before the half turn has no period, and is not met.
  const Rows short_run = jeffery_rows(r, shear_rate, 0.0, 0.3 * period, 0.01);
  const rouleau::JefferyComparison unfinished =
      rouleau::compare_with_jeffery(short_run.times, short_run.angles, r, shear_rate);
  EXPECT_LT(unfinished.measured_period, 0.0);
  EXPECT_FALSE(unfinished.met());
  EXPECT_THROW(rouleau::compare_with_jeffery({0.0}, {0.0}, r, shear_rate), std::invalid_argument);
}

}  // namespace
