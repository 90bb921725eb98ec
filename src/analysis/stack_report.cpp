#include "analysis/stack_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace rouleau {

int cells_per_column(const CaseConfig& config) {
  int count = 0;
  for (const auto& cell : config.cells)
    if (std::fabs(cell.center[0] - config.cells.front().center[0]) < 0.5) ++count;
  return count;
}

std::vector<PaperCheckRow> print_stack_report(const CaseConfig& config, const DiagnosticsRows& rows) {
  const int cells = static_cast<int>(config.cells.size());
  const int per_column = cells_per_column(config);
  // A gap is reported between neighbours in the same column.
  const auto same_column = [&](int c) { return (c + 1) % per_column != 0; };
  std::printf("%9s", "time_s");
  for (int c = 0; c < cells; ++c) std::printf("  incl%-3d", c);
  for (int c = 0; c + 1 < cells; ++c)
    if (same_column(c)) std::printf("  gap%d_%-3d", c, c + 1);
  std::printf("\n");
  for (const auto& row : rows) {
    std::printf("%9.4f", row.at("time_s"));
    for (int c = 0; c < cells; ++c) std::printf(" %8.2f", row.at("cell" + std::to_string(c) + "_inclination_deg"));
    for (int c = 0; c + 1 < cells; ++c)
      if (same_column(c)) std::printf(" %9.4f", row.at("gap_" + std::to_string(c) + "_" + std::to_string(c + 1) + "_um"));
    std::printf("\n");
  }
  // The shear rate from the walls: (u_top − u_bottom) / H.
  const auto& domain = config.domain;
  const double shear_rate =
      (domain.boundary[Side::y_max].velocity[0] - domain.boundary[Side::y_min].velocity[0]) /
      (domain.upper[1] - domain.lower[1]);
  const double r0 = config.interaction.morse.zero_force_length;
  const StackMeasures m = measure_stack(rows, cells, per_column, r0);
  const double end = rows.back().at("time_s");
  std::printf("shear rate %.3g 1/s, t = %.4g s (strain %.3g): neighbour gap growth %.4f to %.4f um, largest "
              "change of a vertical separation %.4f um, mean inclination %.2f deg (spread %.2f), stack axis %.2f deg, %s\n",
              shear_rate, end, shear_rate * end, m.smallest_gap_growth, m.largest_gap_growth, m.largest_separation_change,
              m.mean_inclination_deg, m.inclination_spread_deg, m.stack_axis_deg, m.intact ? "intact" : "broken up");
  // The paper's statement for this run, as measures against thresholds.
  const StackStatement check =
      check_stack_statement(m, shear_rate, config.interaction.enabled, r0, cells / std::max(per_column, 1));
  std::vector<PaperCheckRow> paper;
  if (rows.front().count("interaction_rim_share")) {
    // Fig. 7: where on the surfaces the interaction acts.
    const RimInteractionCheck rims = check_interaction_at_rims(rows);
    std::printf("check (Fig. 7, the interaction acts mainly at the rims): the rims' smallest share of the force "
                "%.3f > %.1f: %s (t = %.3f s), force per area %.2f times that elsewhere >= %.1f: %s (the rims %.2f of "
                "the surface): %s\n",
                rims.smallest_share, RimInteractionCheck::least_share,
                rims.smallest_share > RimInteractionCheck::least_share ? "yes" : "NO", rims.smallest_share_time,
                rims.density_ratio, RimInteractionCheck::least_density_ratio,
                rims.density_ratio >= RimInteractionCheck::least_density_ratio ? "yes" : "NO", rims.area_share,
                rims.met ? "met" : "NOT MET");
    paper = paper_rows(rims, rims.smallest_share > 0.0);
  }
  std::printf("check (%s, %s): %s: %s\n", check.figure.c_str(), check.statement.c_str(), check.measured.c_str(),
              check.met ? "met" : (check.long_enough ? "NOT MET" : "NOT MET (the run is shorter than the paper's)"));
  const std::vector<PaperCheckRow> stack = paper_rows(check);
  paper.insert(paper.end(), stack.begin(), stack.end());
  return paper;
}

}  // namespace rouleau
