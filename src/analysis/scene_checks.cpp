#include "analysis/scene_checks.hpp"

#include <algorithm>
#include <stdexcept>

namespace rouleau {

std::vector<double> diagnostics_column(const DiagnosticsRows& rows, const std::string& column) {
  std::vector<double> values;
  values.reserve(rows.size());
  for (const auto& row : rows) {
    const auto found = row.find(column);
    if (found == row.end()) throw std::runtime_error("rouleau::diagnostics_column: no column \"" + column + "\"");
    values.push_back(found->second);
  }
  return values;
}

AggregationCheck check_aggregation(const DiagnosticsRows& rows, double zero_force_length, int a, int b) {
  const std::string pair = std::to_string(a) + "_" + std::to_string(b);
  const std::vector<double> gap = diagnostics_column(rows, "gap_" + pair + "_um");
  const std::vector<double> area = diagnostics_column(rows, "contact_area_" + pair + "_um2");
  const std::vector<double> time = diagnostics_column(rows, "time_s");
  if (gap.empty()) throw std::runtime_error("rouleau::check_aggregation: no diagnostics rows");
  AggregationCheck check;
  check.initial_gap = gap.front();
  check.final_gap = gap.back();
  check.final_contact_area = area.back();
  // The last quarter of the run in time: rows from t ≥ t0 + ¾ (t_end − t0).
  const double settle_from = time.front() + 0.75 * (time.back() - time.front());
  double smallest = gap.back(), largest = gap.back();
  for (std::size_t i = 0; i < gap.size(); ++i)
    if (time[i] >= settle_from) {
      smallest = std::min(smallest, gap[i]);
      largest = std::max(largest, gap[i]);
    }
  check.settled_gap_range = largest - smallest;
  check.closed = check.final_gap < AggregationCheck::closed_gap_r0 * zero_force_length;
  check.settled = check.settled_gap_range < AggregationCheck::settled_range_r0 * zero_force_length;
  check.open = check.final_gap >= AggregationCheck::open_fraction * check.initial_gap;
  return check;
}

}  // namespace rouleau
