#pragma once
// The paper's scenes say in numbers whether they reproduced what the paper reports: each
// check reads a run's diagnostics (io/diagnostics_reader.hpp), measures the quantities the
// paper's statement is about, and compares them with stated thresholds. Case drivers print
// them; the reduced scenes in CI assert them. Host-only.
#include <map>
#include <string>
#include <vector>

namespace rouleau {

using DiagnosticsRows = std::vector<std::map<std::string, double>>;

// The values of one column over the run, in row order. Throws std::runtime_error naming the
// column when the rows lack it.
std::vector<double> diagnostics_column(const DiagnosticsRows& rows, const std::string& column);

// Two cells aggregating in quiescent plasma (Liu et al. 2004, Fig. 6): the gap between
// them (gap_A_B_um, the least distance between their outer surfaces) "closes to the
// order of r0 and stays there".
struct AggregationCheck {
  double initial_gap = 0.0;         // [μm] first row
  double final_gap = 0.0;           // [μm] last row
  double settled_gap_range = 0.0;   // [μm] largest − smallest gap over the run's last quarter (in time)
  double final_contact_area = 0.0;  // [μm²] surface closer than r0, last row
  // Thresholds, in units of r0: closed when the final gap is below closed_gap_r0 · r0;
  // settled when the last quarter's range is below settled_range_r0 · r0.
  static constexpr double closed_gap_r0 = 1.5;
  static constexpr double settled_range_r0 = 0.2;
  bool closed = false;
  bool settled = false;
  // Without interaction the gap must not close: open when final ≥ 0.9 · initial.
  static constexpr double open_fraction = 0.9;
  bool open = false;
};

// Measures the check between cells `a` and `b` (indices) for Morse length r0 [μm].
AggregationCheck check_aggregation(const DiagnosticsRows& rows, double zero_force_length, int a = 0, int b = 1);

}  // namespace rouleau
