#include "analysis/scene_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "util/constants.hpp"

namespace rouleau {

double diagnostics_value(const std::map<std::string, double>& row, const std::string& column) {
  const auto found = row.find(column);
  if (found == row.end()) throw std::runtime_error("rouleau: the diagnostics have no column \"" + column + "\"");
  return found->second;
}

std::vector<double> diagnostics_column(const DiagnosticsRows& rows, const std::string& column) {
  std::vector<double> values;
  values.reserve(rows.size());
  for (const auto& row : rows) values.push_back(diagnostics_value(row, column));
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

int cells_past(const std::map<std::string, double>& row, int cells, double x) {
  int past = 0;
  for (int c = 0; c < cells; ++c)
    if (diagnostics_value(row, "cell" + std::to_string(c) + "_centroid_x_um") > x) ++past;
  return past;
}

ContractionPassageCheck check_contraction_passage(const DiagnosticsRows& rows, const std::vector<std::string>& kinds,
                                                  double throat_entry, double throat_exit) {
  if (rows.empty()) throw std::runtime_error("rouleau::check_contraction_passage: no diagnostics rows");
  ContractionPassageCheck check;
  const int cells = static_cast<int>(kinds.size());
  check.passage_time.assign(cells, -1.0);
  const std::vector<double> time = diagnostics_column(rows, "time_s");
  check.end_time = time.back();
  // The rows of the run's first and last quarter in time (at least two each).
  const double quarter = 0.25 * (time.back() - time.front());
  std::size_t first_end = 1, last_begin = rows.size() >= 2 ? rows.size() - 2 : 0;
  while (first_end + 1 < rows.size() && time[first_end] < time.front() + quarter) ++first_end;
  while (last_begin > 0 && time[last_begin] > time.back() - quarter) --last_begin;
  // The mean speed along x over rows [a, b].
  auto mean_speed = [&time](const std::vector<double>& x, std::size_t a, std::size_t b) {
    return time[b] > time[a] ? (x[b] - x[a]) / (time[b] - time[a]) : 0.0;
  };
  std::vector<double> front(cells), rear(cells);
  std::vector<bool> stalled(cells);
  for (int c = 0; c < cells; ++c) {
    const std::string cell = "cell" + std::to_string(c);
    const std::vector<double> x = diagnostics_column(rows, cell + "_centroid_x_um");
    for (std::size_t r = 0; r < rows.size() && check.passage_time[c] < 0.0; ++r)
      if (x[r] > throat_exit) check.passage_time[c] = time[r];
    check.final_position.push_back(x.back());
    check.passed.push_back(x.back() > throat_exit);
    const double half_length = 0.5 * diagnostics_value(rows.back(), cell + "_extent_x_um");
    front[c] = x.back() + half_length;
    rear[c] = x.back() - half_length;
    const double early = rows.size() >= 3 ? mean_speed(x, 0, first_end) : 0.0;
    const double late = rows.size() >= 3 ? mean_speed(x, last_begin, rows.size() - 1) : 0.0;
    check.late_speed_ratio.push_back(early > 0.0 ? late / early : INFINITY);
    stalled[c] = rows.size() >= 3 && check.late_speed_ratio.back() < ContractionPassageCheck::stalled_speed_fraction;
  }
  // The queue, front first: a stalled cell is blocked when its front is within
  // blocked_front_distance of what holds it, the entry or the rearmost blocked cell ahead.
  std::vector<int> front_first(cells);
  for (int c = 0; c < cells; ++c) front_first[c] = c;
  std::sort(front_first.begin(), front_first.end(), [&front](int a, int b) { return front[a] > front[b]; });
  check.blocked.assign(cells, false);
  check.front_before_hold.assign(cells, 0.0);
  double hold = throat_entry;
  for (int c : front_first) {
    check.front_before_hold[c] = hold - front[c];
    check.blocked[c] = !check.passed[c] && stalled[c] &&
                       check.front_before_hold[c] <= ContractionPassageCheck::blocked_front_distance;
    if (check.blocked[c]) hold = std::min(hold, rear[c]);
  }
  if (rows.back().count("relative_apparent_viscosity"))
    check.final_pressure_ratio = rows.back().at("relative_apparent_viscosity");
  bool all_normal_passed = true, all_sickle_blocked = true;
  for (int c = 0; c < cells; ++c) {
    if (kinds[c] == "sickle") {
      ++check.sickle_cells;
      all_sickle_blocked = all_sickle_blocked && check.blocked[c];
    } else {
      ++check.normal_cells;
      all_normal_passed = all_normal_passed && check.passed[c];
    }
  }
  check.normal_cells_passed = check.normal_cells > 0 && all_normal_passed;
  check.sickle_cells_blocked = check.sickle_cells > 0 && all_sickle_blocked &&
                               check.final_pressure_ratio >= ContractionPassageCheck::blocked_pressure_ratio;
  if (rows.front().count("smallest_volume_ratio")) {
    const std::vector<double> volume_ratio = diagnostics_column(rows, "smallest_volume_ratio");
    const auto smallest = std::min_element(volume_ratio.begin(), volume_ratio.end());
    check.smallest_volume_ratio = *smallest;
    check.smallest_volume_ratio_time = diagnostics_value(rows[smallest - volume_ratio.begin()], "time_s");
  }
  check.no_element_crushed = check.smallest_volume_ratio > ContractionPassageCheck::crushed_volume_ratio;
  return check;
}

namespace {

// The mean speed along x of `x` (over `time`) while it crosses [start, end]: from the first
// row at or past `start` to the first row past `end`, or the last row; 0 when it never
// reached `start` or stayed in one row.
double crossing_speed(const std::vector<double>& x, const std::vector<double>& time, double start, double end) {
  std::size_t first = 0;
  while (first < x.size() && x[first] < start) ++first;
  if (first >= x.size()) return 0.0;
  std::size_t last = first;
  while (last + 1 < x.size() && x[last] <= end) ++last;
  return time[last] > time[first] ? (x[last] - x[first]) / (time[last] - time[first]) : 0.0;
}

// The mean distance between neighbours of `positions` once sorted.
double mean_neighbour_distance(std::vector<double> positions) {
  std::sort(positions.begin(), positions.end());
  return (positions.back() - positions.front()) / static_cast<double>(positions.size() - 1);
}

}  // namespace

ContractionOutletCheck check_contraction_outlet(const DiagnosticsRows& rows, const std::vector<std::string>& kinds,
                                                double throat_entry, double throat_exit, double diffuser_exit) {
  if (rows.empty()) throw std::runtime_error("rouleau::check_contraction_outlet: no diagnostics rows");
  ContractionOutletCheck check;
  const std::vector<double> time = diagnostics_column(rows, "time_s");
  std::vector<std::vector<double>> x;
  for (std::size_t c = 0; c < kinds.size(); ++c) {
    if (kinds[c] == "sickle") continue;
    check.cells.push_back(static_cast<int>(c));
    x.push_back(diagnostics_column(rows, "cell" + std::to_string(c) + "_centroid_x_um"));
    check.throat_speed.push_back(crossing_speed(x.back(), time, throat_entry, throat_exit));
    check.diffuser_speed.push_back(crossing_speed(x.back(), time, throat_exit, diffuser_exit));
  }
  if (x.size() < 2) return check;
  std::vector<double> at(x.size());
  for (std::size_t c = 0; c < x.size(); ++c) at[c] = x[c].front();
  check.initial_spacing = mean_neighbour_distance(at);
  for (std::size_t r = 0; r < rows.size(); ++r) {
    bool all = true;
    for (std::size_t c = 0; c < x.size(); ++c) {
      at[c] = x[c][r];
      all = all && x[c][r] > throat_exit;
    }
    if (!all) continue;
    check.time_all_passed = time[r];
    check.spacing_after = mean_neighbour_distance(at);
    if (check.initial_spacing > 0.0) check.spacing_ratio = check.spacing_after / check.initial_spacing;
    break;
  }
  return check;
}

CapillaryPassageCheck check_capillary_passage(const DiagnosticsRows& rows, double entry, double exit) {
  if (rows.empty()) throw std::runtime_error("rouleau::check_capillary_passage: no diagnostics rows");
  const std::vector<double> pressure = diagnostics_column(rows, "driving_pressure_Pa");
  const std::vector<double> position = diagnostics_column(rows, "cell0_centroid_x_um");
  const std::vector<double> length = diagnostics_column(rows, "cell0_extent_x_um");
  CapillaryPassageCheck check;
  // The row of step 0 holds the fluid as it starts, before any solve has driven it (no
  // pressure drop yet): the pressures are taken from the rows after it.
  const std::size_t first_driven =
      rows.size() > 1 && rows.front().count("step") && rows.front().at("step") == 0.0 ? 1 : 0;
  check.initial_pressure = pressure[first_driven];
  check.final_pressure = pressure.back();
  check.final_position = position.back();
  check.free_length = length.front();
  check.peak_pressure = pressure[first_driven];
  check.peak_position = position[first_driven];
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i >= first_driven && pressure[i] > check.peak_pressure) {
      check.peak_pressure = pressure[i];
      check.peak_position = position[i];
    }
    if (position[i] >= entry && position[i] <= exit) check.longest_inside = std::max(check.longest_inside, length[i]);
  }
  // The plateau: the rows with the whole capsule inside, rear ≥ entry and front ≤ exit.
  double lowest = HUGE_VAL, highest = -HUGE_VAL, sum = 0.0;
  for (std::size_t i = first_driven; i < rows.size(); ++i) {
    const double rear = position[i] - 0.5 * length[i], front = position[i] + 0.5 * length[i];
    if (rear < entry || front > exit) continue;
    ++check.plateau_rows;
    sum += pressure[i];
    lowest = std::min(lowest, pressure[i]);
    highest = std::max(highest, pressure[i]);
  }
  if (check.plateau_rows > 0) {
    check.plateau_mean = sum / check.plateau_rows;
    check.plateau_spread = (highest - lowest) / check.plateau_mean;
  }
  // The flare: R_rear / R_front while the rear is out by less than the free length.
  if (rows.front().count("cell0_radius_rear_um")) {
    const std::vector<double> rear_radius = diagnostics_column(rows, "cell0_radius_rear_um");
    const std::vector<double> front_radius = diagnostics_column(rows, "cell0_radius_front_um");
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const double rear = position[i] - 0.5 * length[i];
      if (rear < exit || rear > exit + check.free_length || front_radius[i] <= 0.0) continue;
      check.largest_rear_over_front = std::max(check.largest_rear_over_front, rear_radius[i] / front_radius[i]);
    }
  }
  const double rise = check.peak_pressure - check.initial_pressure;
  check.rose = rise >= CapillaryPassageCheck::rise_fraction * check.initial_pressure &&
               check.peak_position >= entry - check.free_length && check.peak_position <= exit + check.free_length;
  check.left = check.final_position > exit + 0.5 * check.free_length;
  check.fell = check.left && check.peak_pressure - check.final_pressure >= CapillaryPassageCheck::fall_fraction * rise;
  check.longer_inside = check.longest_inside > check.free_length;
  check.plateau = check.plateau_rows >= CapillaryPassageCheck::plateau_rows_min &&
                  check.plateau_spread <= CapillaryPassageCheck::plateau_spread_max &&
                  check.plateau_mean >= (1.0 + CapillaryPassageCheck::rise_fraction) * check.initial_pressure;
  check.flared = check.largest_rear_over_front >= CapillaryPassageCheck::flare_ratio;
  return check;
}

RimInteractionCheck check_interaction_at_rims(const DiagnosticsRows& rows) {
  RimInteractionCheck check;
  bool any = false;
  for (const auto& row : rows) {
    const double share = diagnostics_value(row, "interaction_rim_share");
    if (share <= 0.0) continue;  // no force in this row
    if (!any || share < check.smallest_share) {
      check.smallest_share = share;
      check.smallest_share_time = diagnostics_value(row, "time_s");
      check.area_share = diagnostics_value(row, "rim_area_share");
    }
    any = true;
  }
  if (!any) return check;
  // Force per area in the bands over that on the rest of the surface.
  const double in_band = check.smallest_share / check.area_share;
  const double elsewhere = (1.0 - check.smallest_share) / (1.0 - check.area_share);
  check.density_ratio = elsewhere > 0.0 ? in_band / elsewhere : INFINITY;
  check.met = check.smallest_share > RimInteractionCheck::least_share &&
              check.density_ratio >= RimInteractionCheck::least_density_ratio;
  return check;
}

StackMeasures measure_stack(const DiagnosticsRows& rows, int cells, int cells_per_stack, double zero_force_length) {
  if (rows.empty()) throw std::runtime_error("rouleau::measure_stack: no diagnostics rows");
  StackMeasures m;
  const auto& first = rows.front();
  const auto& last = rows.back();
  // Cell c's value of `what` (a cellC_ column) in `row`.
  auto of_cell = [](const std::map<std::string, double>& row, int c, const char* what) {
    return diagnostics_value(row, "cell" + std::to_string(c) + "_" + what);
  };
  auto y = [&](const std::map<std::string, double>& row, int c) { return of_cell(row, c, "centroid_y_um"); };
  m.largest_gap_growth = -1e300;
  m.smallest_gap_growth = 1e300;
  for (int c = 0; c + 1 < cells; ++c) {
    if ((c + 1) % cells_per_stack == 0) continue;  // c is the top of its column
    const std::string gap = "gap_" + std::to_string(c) + "_" + std::to_string(c + 1) + "_um";
    const double growth = diagnostics_value(last, gap) - diagnostics_value(first, gap);
    m.largest_gap_growth = std::max(m.largest_gap_growth, growth);
    m.smallest_gap_growth = std::min(m.smallest_gap_growth, growth);
    const double separation_change = (y(last, c + 1) - y(last, c)) - (y(first, c + 1) - y(first, c));
    m.largest_separation_change = std::max(m.largest_separation_change, std::fabs(separation_change));
  }
  // Inclinations are axes, the same modulo 180° (a disc at −89° and one at +89° are 2°
  // apart). Their mean is half the angle of the mean doubled-angle vector,
  // ½ atan2(Σ sin 2θ, Σ cos 2θ), in (−90°, 90°]; their spread the shortest arc of the
  // half-circle that holds them all, 180° less the widest gap between neighbours on it.
  std::vector<double> axes;
  double sin_sum = 0.0, cos_sum = 0.0;
  for (int c = 0; c < cells; ++c) {
    const double inclination = of_cell(last, c, "inclination_deg");
    sin_sum += std::sin(2.0 * inclination * pi / 180.0);
    cos_sum += std::cos(2.0 * inclination * pi / 180.0);
    axes.push_back(inclination - 180.0 * std::floor(inclination / 180.0));  // in [0, 180)
  }
  m.mean_inclination_deg = 0.5 * std::atan2(sin_sum, cos_sum) * 180.0 / pi;
  std::sort(axes.begin(), axes.end());
  double widest_gap = axes.empty() ? 180.0 : 180.0 - (axes.back() - axes.front());
  for (std::size_t i = 1; i < axes.size(); ++i) widest_gap = std::max(widest_gap, axes[i] - axes[i - 1]);
  m.inclination_spread_deg = 180.0 - widest_gap;
  const int top = std::min(cells_per_stack, cells) - 1;
  const double dx = of_cell(last, top, "centroid_x_um") - of_cell(last, 0, "centroid_x_um");
  const double dy = y(last, top) - y(last, 0);
  m.stack_axis_deg = std::atan2(dx, dy) * 180.0 / pi;
  m.duration = diagnostics_value(last, "time_s") - diagnostics_value(first, "time_s");
  m.intact = m.largest_gap_growth < zero_force_length;
  return m;
}

StackStatement check_stack_statement(const StackMeasures& m, double shear_rate, bool interaction,
                                     double zero_force_length, int columns) {
  StackStatement result;
  std::vector<PaperMeasure> parts;
  if (!interaction) {
    result.figure = "Fig. 8";
    result.statement = "no interaction: the cells keep their vertical separations";
    result.required_strain = 0.25 * 4.0;
    parts.push_back(measure_against("largest separation change", m.largest_separation_change, "<", 0.5, "um"));
  } else if (shear_rate <= 0.3) {
    result.figure = "Fig. 9";
    result.statement = "0.25 1/s: the stack rotates as one body";
    result.required_strain = 0.25 * 4.0;
    parts.push_back(measure_against("largest gap growth (threshold r0)", m.largest_gap_growth, "<", zero_force_length, "um"));
    parts.push_back(measure_against("|axis + inclination|", std::fabs(m.stack_axis_deg + m.mean_inclination_deg), "<", 10.0,
                            "deg"));
  } else if (shear_rate <= 1.0) {
    result.figure = "Fig. 10";
    result.statement = "0.5 1/s: the stack aligns with the flow and starts to separate";
    result.required_strain = 0.5 * 1.0;
    parts.push_back(measure_against("largest gap growth (threshold r0)", m.largest_gap_growth, ">", zero_force_length, "um"));
    parts.push_back(measure_against("|mean inclination|", std::fabs(m.mean_inclination_deg), "<", 20.0, "deg"));
  } else {
    const bool twelve = columns > 1;
    result.figure = twelve ? "Fig. 12" : "Fig. 11";
    result.statement = twelve ? "3.0 1/s: the aggregate partly breaks up and aligns in layers"
                              : "3.0 1/s: the stack breaks up completely into parallel layers";
    result.required_strain = twelve ? 3.0 * 3.0 : 3.0 * 0.5;
    // "Completely" (Fig. 11): every pair of neighbours parted; "partly" (Fig. 12): one did.
    if (twelve)
      parts.push_back(measure_against("largest gap growth (threshold r0)", m.largest_gap_growth, ">", zero_force_length, "um"));
    else
      parts.push_back(measure_against("smallest gap growth (threshold r0)", m.smallest_gap_growth, ">", zero_force_length, "um"));
    parts.push_back(measure_against("inclination spread", m.inclination_spread_deg, "<", 10.0, "deg"));
  }
  result.strain = shear_rate * m.duration;
  // The strain to 1e-6, so that the last row's time reaches the paper's within round-off.
  const double strain = std::round(result.strain * 1e6) / 1e6;
  result.measures.push_back(measure_against("strain (threshold: the paper's)", strain, ">=", result.required_strain, ""));
  result.long_enough = result.measures.front().met;
  result.measures.insert(result.measures.end(), parts.begin(), parts.end());
  result.met = true;
  for (const PaperMeasure& measure : result.measures) {
    result.met = result.met && measure.met;
    result.measured += (result.measured.empty() ? "" : ", ") + measure.text();
  }
  return result;
}

}  // namespace rouleau
