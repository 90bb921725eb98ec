#include "analysis/paper_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/atomic_file.hpp"

namespace rouleau {

namespace {
const char* const fig14_statement = "normal cells pass the throat, slow down in the diffuser and pile up at the outlet";
}  // namespace

std::vector<PaperCheckRow> paper_rows(const AggregationCheck& check, double zero_force_length, bool interaction) {
  if (!interaction) return {};
  const std::string figure = "Fig. 6", statement = "two cells aggregate: the gap closes to the order of r0 and stays";
  return {
      {figure, statement,
       measure_against("final gap (threshold 1.5 r0)", check.final_gap, "<",
                       AggregationCheck::closed_gap_r0 * zero_force_length, "um")},
      {figure, statement,
       measure_against("gap's range over the run's last quarter (threshold 0.2 r0)", check.settled_gap_range, "<",
                       AggregationCheck::settled_range_r0 * zero_force_length, "um")},
  };
}

std::vector<PaperCheckRow> paper_rows(const RimInteractionCheck& check, bool forces_acted) {
  if (!forces_acted) return {};
  const std::string figure = "Fig. 7", statement = "the interaction forces act mainly at the rims";
  return {
      {figure, statement,
       measure_against("the rims' smallest share of the interaction force", check.smallest_share, ">",
                       RimInteractionCheck::least_share, "")},
      {figure, statement,
       measure_against("force per area at the rims over that elsewhere", check.density_ratio, ">=",
                       RimInteractionCheck::least_density_ratio, "")},
  };
}

std::vector<PaperCheckRow> paper_rows(const StackStatement& statement) {
  std::vector<PaperCheckRow> rows;
  for (const PaperMeasure& measure : statement.measures) rows.push_back({statement.figure, statement.statement, measure});
  return rows;
}

std::vector<PaperCheckRow> paper_rows(const ContractionPassageCheck& check, const std::vector<std::string>& kinds,
                                      double throat_exit) {
  using Check = ContractionPassageCheck;
  std::vector<PaperCheckRow> rows;
  for (std::size_t c = 0; c < kinds.size(); ++c) {
    const std::string cell = "cell " + std::to_string(c);
    if (kinds[c] != "sickle") {
      rows.push_back({"Fig. 14", fig14_statement,
                      measure_against(cell + ": centroid's x at the end, past the throat's exit", check.final_position[c],
                                      ">", throat_exit, "um")});
      continue;
    }
    const std::string figure = "Fig. 15", statement = "sickle cells block the throat's entrance";
    rows.push_back({figure, statement,
                    measure_against(cell + ": centroid's x at the end, before the throat's exit", check.final_position[c],
                                    "<=", throat_exit, "um")});
    rows.push_back({figure, statement,
                    measure_against(cell + ": its front's distance before the throat's entry or the blocked cell ahead",
                                    check.front_before_hold[c], "<=", Check::blocked_front_distance, "um")});
    rows.push_back({figure, statement,
                    measure_against(cell + ": its speed over the last quarter over that over the first",
                                    check.late_speed_ratio[c], "<", Check::stalled_speed_fraction, "")});
  }
  if (check.sickle_cells > 0)
    rows.push_back({"Fig. 15", "sickle cells block the throat's entrance",
                    measure_against("driving pressure over Hagen-Poiseuille's at the same flow, at the end",
                                    check.final_pressure_ratio, ">=", Check::blocked_pressure_ratio, "")});
  return rows;
}

std::vector<PaperCheckRow> paper_rows(const ContractionOutletCheck& check) {
  using Check = ContractionOutletCheck;
  std::vector<PaperCheckRow> rows;
  for (std::size_t i = 0; i < check.cells.size(); ++i) {
    const double throat = check.throat_speed[i];
    rows.push_back({"Fig. 14", fig14_statement,
                    measure_against("cell " + std::to_string(check.cells[i]) +
                                        ": its speed across the diffuser over that across the throat",
                                    throat > 0.0 ? check.diffuser_speed[i] / throat : INFINITY, "<",
                                    Check::slower_fraction, "")});
  }
  if (check.cells.size() >= 2)
    rows.push_back({"Fig. 14", fig14_statement,
                    measure_against("the normal cells' neighbour spacing when the last has passed the throat, over "
                                    "the initial spacing",
                                    check.spacing_ratio, "<", Check::closer_fraction, "")});
  return rows;
}

std::vector<PaperCheckRow> paper_rows(const CapillaryPassageCheck& check, double entry, double exit) {
  using Check = CapillaryPassageCheck;
  std::vector<PaperCheckRow> rows;
  const std::string shape = "inside the capillary the capsule is longer than its free diameter (a slug) and it "
                            "leaves with its rear flared (a jellyfish)";
  rows.push_back({"Fig. 16", shape,
                  measure_against("longest x-extent inside over the free one",
                                  check.free_length > 0.0 ? check.longest_inside / check.free_length : 0.0, ">", 1.0,
                                  "")});
  rows.push_back({"Fig. 16", shape,
                  measure_against("largest rear over front radius within a free length past the exit",
                                  check.largest_rear_over_front, ">=", Check::flare_ratio, "")});
  const std::string figure = "Fig. 17",
                    statement = "the driving pressure rises while the capsule enters, stays up while it plugs the "
                                "capillary and falls after it leaves";
  const double rise = check.peak_pressure - check.initial_pressure;
  rows.push_back({figure, statement,
                  measure_against("peak pressure's rise over the initial pressure",
                                  check.initial_pressure > 0.0 ? rise / check.initial_pressure : 0.0, ">=",
                                  Check::rise_fraction, "")});
  rows.push_back({figure, statement,
                  measure_against("capsule's centroid's distance from the capillary at the peak (threshold: its free length)",
                                  std::max({0.0, entry - check.peak_position, check.peak_position - exit}), "<=",
                                  check.free_length, "um")});
  rows.push_back({figure, statement,
                  measure_against("rows with the capsule wholly inside", check.plateau_rows, ">=",
                                  Check::plateau_rows_min, "")});
  rows.push_back({figure, statement,
                  measure_against("pressure's spread over its mean while wholly inside",
                                  check.plateau_rows > 0 ? check.plateau_spread : 0.0, "<=", Check::plateau_spread_max,
                                  "")});
  rows.push_back({figure, statement,
                  measure_against("pressure's mean while wholly inside over the initial pressure, less 1",
                                  check.initial_pressure > 0.0 && check.plateau_rows > 0
                                      ? check.plateau_mean / check.initial_pressure - 1.0
                                      : 0.0,
                                  ">=", Check::rise_fraction, "")});
  rows.push_back({figure, statement,
                  measure_against("capsule's centroid at the end, past the exit", check.final_position, ">",
                                  exit + 0.5 * check.free_length, "um")});
  rows.push_back({figure, statement,
                  measure_against("pressure's fall at the end over its rise",
                                  rise > 0.0 ? (check.peak_pressure - check.final_pressure) / rise : 0.0, ">=",
                                  Check::fall_fraction, "")});
  return rows;
}

namespace {

// A CSV field: quoted, with its quotes doubled.
std::string quoted(const std::string& text) {
  std::string field = "\"";
  for (char c : text) field += c == '"' ? std::string("\"\"") : std::string(1, c);
  return field + "\"";
}

}  // namespace

std::string paper_checks_csv(const std::vector<PaperCheckRow>& rows) {
  std::string csv = "figure,statement,metric,value,relation,threshold,unit,met\n";
  for (const PaperCheckRow& row : rows) {
    char numbers[96];
    std::snprintf(numbers, sizeof(numbers), "%.6g,%s,%.6g", row.measure.value, quoted(row.measure.relation).c_str(),
                  row.measure.threshold);
    csv += quoted(row.figure) + "," + quoted(row.statement) + "," + quoted(row.measure.metric) + "," + numbers + "," +
           quoted(row.measure.unit) + "," + (row.measure.met ? "1" : "0") + "\n";
  }
  return csv;
}

void write_paper_checks(const std::string& run_dir, const std::vector<PaperCheckRow>& rows) {
  write_file_atomically(run_dir + "/" + paper_checks_name, paper_checks_csv(rows));
}

}  // namespace rouleau
