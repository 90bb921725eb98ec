#include "analysis/sphere_in_tube.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include "util/constants.hpp"

namespace rouleau {

double sphere_in_tube_speed_ratio(double radius_ratio) {
  const double lambda = radius_ratio;
  if (!(lambda >= 0.0 && lambda < 1.0))
    throw std::invalid_argument("sphere_in_tube_speed_ratio: a/R must lie in [0, 1), got " + std::to_string(lambda));
  const double gap = 1.0 - lambda, l2 = lambda * lambda, l3 = l2 * lambda, l4 = l3 * lambda;
  const double lubrication = 9.0 / 4.0 * pi * pi * std::sqrt(2.0) * std::pow(gap, -2.5);
  const double translation = lubrication * (1.0 - 73.0 / 60.0 * gap + 77293.0 / 50400.0 * gap * gap) - 22.5083 -
                             5.6117 * lambda - 0.3363 * l2 - 1.216 * l3 + 1.647 * l4;
  const double flow = lubrication * (1.0 + 7.0 / 60.0 * gap - 2227.0 / 50400.0 * gap * gap) + 4.0180 -
                      3.9788 * lambda - 1.9215 * l2 + 4.392 * l3 + 5.006 * l4;
  return flow / translation;
}

PlugSpeed measure_plug_speed(const DiagnosticsRows& rows, double from_time, int cell) {
  const std::string column = "cell" + std::to_string(cell) + "_centroid_x_um";
  std::vector<double> times, positions;
  for (const auto& row : rows) {
    const double t = diagnostics_value(row, "time_s");
    if (t < from_time) continue;
    times.push_back(t);
    positions.push_back(diagnostics_value(row, column));
  }
  if (times.size() < 3)
    throw std::runtime_error("measure_plug_speed: fewer than 3 rows at or after t = " + std::to_string(from_time) + " s");
  // Slope of the least-squares line x = x̄ + U (t − t̄).
  double mean_t = 0.0, mean_x = 0.0;
  for (std::size_t k = 0; k < times.size(); ++k) mean_t += times[k], mean_x += positions[k];
  mean_t /= times.size(), mean_x /= times.size();
  double covariance = 0.0, variance = 0.0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    covariance += (times[k] - mean_t) * (positions[k] - mean_x);
    variance += (times[k] - mean_t) * (times[k] - mean_t);
  }
  PlugSpeed result;
  result.speed = covariance / variance;
  result.rows = static_cast<int>(times.size());
  double slowest = INFINITY, fastest = -INFINITY;
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double speed = (positions[k] - positions[k - 1]) / (times[k] - times[k - 1]);
    slowest = std::min(slowest, speed), fastest = std::max(fastest, speed);
  }
  result.speed_spread = fastest - slowest;
  return result;
}

}  // namespace rouleau
