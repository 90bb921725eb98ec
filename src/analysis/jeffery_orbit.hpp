#pragma once
// A rigid spheroid's rotation in simple shear (Jeffery 1922) and the comparison of a run's
// cell with it. Host-only.
//
// Flow u = γ̇ y e_x (vorticity −γ̇ e_z). A spheroid with its symmetry axis p in the shear
// plane, at the angle φ from the gradient axis y toward the flow axis x, p = (sin φ, cos φ, 0),
// turns at
//   dφ/dt = γ̇ (r² cos²φ + sin²φ) / (r² + 1),                               (Jeffery 1922)
// r = polar / equatorial semi-axis (r < 1 oblate, r > 1 prolate), whose solution is
//   tan φ = r tan ψ,   ψ = ψ0 + ω t,   ω = γ̇ r / (r² + 1),
// so that p turns by π in half the period T = 2π (r + 1/r) / γ̇ and by 2π in T.
#include <vector>

namespace rouleau {

// The angle φ [rad] at time t [s] of the orbit through φ0 at t = 0: continuous in t
// (φ and ψ cross the multiples of π/2 together).
double jeffery_angle(double time, double axis_ratio, double shear_rate, double initial_angle);
// T = 2π (r + 1/r) / γ̇ [s].
double jeffery_period(double axis_ratio, double shear_rate);

// The symmetry axis's angle φ [rad] from the cell's inclination in the shear plane (the
// major axis of its cross-section's second moments, from the flow axis x, counter-
// clockwise, in (−90°, 90°]): an oblate body's major axis lies across p (φ = −θ), a
// prolate one's along it (φ = π/2 − θ). The inclinations are unwrapped (a jump of more
// than 90° between rows is a turn through ±90°, not back).
std::vector<double> symmetry_axis_angles(const std::vector<double>& inclination_deg, double axis_ratio);

// A run's spheroid against Jeffery's orbit through its first row's angle.
struct JefferyComparison {
  double rms_angle_error_deg = 0.0;   // RMS over the rows of φ_run − φ_Jeffery [°]
  double largest_angle_error_deg = 0.0;
  double half_turn_time = -1.0;       // [s] the first time φ has turned by π (interpolated); −1: never
  double measured_period = -1.0;      // 2 × half_turn_time [s]; −1: no half turn in the run
  double jeffery_period = 0.0;        // [s]
  double period_error = 0.0;          // measured / Jeffery − 1 (when measured)
  // The flip: the time from φ = 45° to 135° (modulo 180°, the first such pass after the
  // first row), where the turning is fastest and a step's lag shows most; −1: not in the
  // run. Jeffery's: (π − 2 atan(1/r)) / ω.
  double flip_time = -1.0;            // [s]
  double jeffery_flip_time = 0.0;     // [s]
  // Thresholds written before the runs (the issue's): the period within 5 %, the angle's
  // history within 5° RMS.
  static constexpr double period_tolerance = 0.05;
  static constexpr double rms_tolerance_deg = 5.0;
  bool met() const {
    return measured_period > 0.0 && period_error < period_tolerance && period_error > -period_tolerance &&
           rms_angle_error_deg < rms_tolerance_deg;
  }
};
// `times` [s] and `angles` φ [rad] (symmetry_axis_angles) of the run's rows, at least two.
JefferyComparison compare_with_jeffery(const std::vector<double>& times, const std::vector<double>& angles,
                                       double axis_ratio, double shear_rate);

}  // namespace rouleau
