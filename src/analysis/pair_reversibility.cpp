#include "analysis/pair_reversibility.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rouleau {

PairReversibility measure_pair_reversibility(const DiagnosticsRows& rows, double radius) {
  if (rows.size() < 2) throw std::runtime_error("measure_pair_reversibility: the run has fewer than 2 rows");
  const auto offset_y = [](const std::map<std::string, double>& row) {
    return diagnostics_value(row, "cell0_centroid_y_um") - diagnostics_value(row, "cell1_centroid_y_um");
  };
  const auto offset_x = [](const std::map<std::string, double>& row) {
    return diagnostics_value(row, "cell0_centroid_x_um") - diagnostics_value(row, "cell1_centroid_x_um");
  };
  PairReversibility result;
  result.initial_offset = result.final_offset = offset_y(rows.front());
  const double start = offset_x(rows.front());  // −d
  result.smallest_gap = diagnostics_value(rows.front(), "gap_0_1_um");
  if (!(start < 0.0)) return result;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    result.smallest_gap = std::min(result.smallest_gap, diagnostics_value(rows[k], "gap_0_1_um"));
    const double before = offset_x(rows[k - 1]), after = offset_x(rows[k]);
    if (before < -start && after >= -start) {
      // Linear between the two rows, at x₀ − x₁ = +d.
      const double s = (-start - before) / (after - before);
      result.final_offset = offset_y(rows[k - 1]) + s * (offset_y(rows[k]) - offset_y(rows[k - 1]));
      const double t0 = diagnostics_value(rows[k - 1], "time_s"), t1 = diagnostics_value(rows[k], "time_s");
      result.symmetric_time = t0 + s * (t1 - t0);
      result.passed = true;
      break;
    }
  }
  result.asymmetry = (result.final_offset - result.initial_offset) / radius;
  return result;
}

}  // namespace rouleau
