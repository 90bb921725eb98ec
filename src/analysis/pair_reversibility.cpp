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
  result.initial_offset = offset_y(rows.front());
  result.final_offset = offset_y(rows.back());
  result.asymmetry = (result.final_offset - result.initial_offset) / radius;
  result.smallest_gap = INFINITY;
  for (const auto& row : rows) result.smallest_gap = std::min(result.smallest_gap, diagnostics_value(row, "gap_0_1_um"));
  const double initial_approach = offset_x(rows.front());
  result.final_approach = offset_x(rows.back());
  result.passed =
      initial_approach < 0.0 && result.final_approach >= PairReversibility::passed_fraction * (-initial_approach);
  return result;
}

}  // namespace rouleau
