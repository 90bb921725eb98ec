#include "analysis/jeffery_orbit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include "util/constants.hpp"

namespace rouleau {
namespace {
// The branch of `base` (defined modulo 2π) within π of `near`.
double nearest_branch(double base, double near) { return base + 2.0 * pi * std::round((near - base) / (2.0 * pi)); }
}  // namespace

double jeffery_period(double axis_ratio, double shear_rate) {
  return 2.0 * pi * (axis_ratio + 1.0 / axis_ratio) / shear_rate;
}

double jeffery_angle(double time, double axis_ratio, double shear_rate, double initial_angle) {
  if (!(axis_ratio > 0.0)) throw std::invalid_argument("jeffery_angle: the axis ratio must be positive");
  // tan ψ = tan φ / r, on φ's branch: ψ = atan2(sin φ / r, cos φ) within π/2 of φ.
  const double r = axis_ratio;
  const double initial_phase =
      nearest_branch(std::atan2(std::sin(initial_angle) / r, std::cos(initial_angle)), initial_angle);
  // ψ = ψ0 + ω t, ω = γ̇ r / (r² + 1); then φ = atan2(r sin ψ, cos ψ) on ψ's branch.
  const double phase = initial_phase + shear_rate * r / (r * r + 1.0) * time;
  return nearest_branch(std::atan2(r * std::sin(phase), std::cos(phase)), phase);
}

std::vector<double> symmetry_axis_angles(const std::vector<double>& inclination_deg, double axis_ratio) {
  std::vector<double> angles;
  angles.reserve(inclination_deg.size());
  double previous = 0.0;
  for (std::size_t k = 0; k < inclination_deg.size(); ++k) {
    double theta = inclination_deg[k] * pi / 180.0;
    // The inclination is defined modulo π: take the branch nearest the previous row's.
    if (k > 0) theta = previous + std::remainder(theta - previous, pi);
    previous = theta;
    angles.push_back(axis_ratio < 1.0 ? -theta : 0.5 * pi - theta);
  }
  return angles;
}

JefferyComparison compare_with_jeffery(const std::vector<double>& times, const std::vector<double>& angles,
                                       double axis_ratio, double shear_rate) {
  if (times.size() != angles.size() || times.size() < 2)
    throw std::invalid_argument("compare_with_jeffery: needs two or more rows with a time and an angle each, got " +
                                std::to_string(times.size()) + " and " + std::to_string(angles.size()));
  JefferyComparison result;
  result.jeffery_period = jeffery_period(axis_ratio, shear_rate);
  const double start = times.front(), initial_angle = angles.front();
  double sum_of_squares = 0.0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double error =
        (angles[k] - jeffery_angle(times[k] - start, axis_ratio, shear_rate, initial_angle)) * 180.0 / pi;
    sum_of_squares += error * error;
    result.largest_angle_error_deg = std::max(result.largest_angle_error_deg, std::abs(error));
    // The half turn: φ passes φ0 + π (the flow turns it toward +φ) between rows k − 1 and k.
    if (k > 0 && result.half_turn_time < 0.0 && angles[k] >= initial_angle + pi) {
      const double before = angles[k - 1] - initial_angle - pi, after = angles[k] - initial_angle - pi;
      result.half_turn_time = times[k - 1] - start + (times[k] - times[k - 1]) * (-before) / (after - before);
    }
  }
  result.rms_angle_error_deg = std::sqrt(sum_of_squares / times.size());
  // The flip: the first angle ≥ φ0 that is 45° modulo 180°, and 90° further.
  const double flip_start = pi / 4 + pi * std::ceil((initial_angle - pi / 4) / pi);
  const auto crossing = [&](double target) {
    for (std::size_t k = 1; k < times.size(); ++k)
      if (angles[k - 1] < target && angles[k] >= target)
        return times[k - 1] + (times[k] - times[k - 1]) * (target - angles[k - 1]) / (angles[k] - angles[k - 1]);
    return -1.0;
  };
  const double flip_begins = crossing(flip_start), flip_ends = crossing(flip_start + pi / 2);
  if (flip_begins >= 0.0 && flip_ends >= 0.0) result.flip_time = flip_ends - flip_begins;
  result.jeffery_flip_time =
      (pi - 2.0 * std::atan(1.0 / axis_ratio)) / (shear_rate * axis_ratio / (axis_ratio * axis_ratio + 1.0));
  if (result.half_turn_time > 0.0) {
    result.measured_period = 2.0 * result.half_turn_time;
    result.period_error = result.measured_period / result.jeffery_period - 1.0;
  }
  return result;
}

}  // namespace rouleau
