#pragma once
// The paper's scenes say in numbers whether they reproduced what the paper reports: each
// check reads a run's diagnostics (io/diagnostics_reader.hpp), measures the quantities the
// paper's statement is about, and compares them with stated thresholds. Case drivers print
// them; the reduced scenes in CI assert them. Host-only.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "analysis/paper_measure.hpp"

namespace rouleau {

using DiagnosticsRows = std::vector<std::map<std::string, double>>;

// The value of one column in a row, and its values over the run in row order. Both throw
// std::runtime_error naming the column when a row lacks it.
double diagnostics_value(const std::map<std::string, double>& row, const std::string& column);
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

// Cells through a vessel (Liu et al. 2004, Figs. 13-17): how many of the run's first
// `cells` cells have their centroid beyond `x` [μm] (the throat's exit) in `row`.
int cells_past(const std::map<std::string, double>& row, int cells, double x);

// Cells through a contraction (Liu et al. 2004, Figs. 13-15): "normal cells pass; sickle
// cells (crescents, stiffer, stickier) block the entrance", within the run's time. The
// throat runs from x = `throat_entry` to `throat_exit` [μm]. A cell has passed when its
// centroid is beyond the throat's exit at the last row. A cell is blocked when it has not
// passed, it has stalled (its mean speed over the run's last quarter, in time, is below
// stalled_speed_fraction of its mean speed over the first quarter), and at the last row
// its front (centroid + half its x-extent) is within blocked_front_distance of what holds
// it, or beyond it: the throat's entry, or the rear of a blocked cell ahead of it (a
// queue; cells are taken front first). A run that ends before a sickle cell reaches the
// entrance, or while it still moves, does not show a blockage. The sickle cells block the
// throat when every one is blocked and the flow is: at the last row the driving pressure
// is at least blocked_pressure_ratio times Hagen–Poiseuille's at the same flow
// (relative_apparent_viscosity; the plasma alone 1.04), so at a fixed driving pressure
// the flow would be at most half the plasma's. `kinds` names each cell's kind: "sickle"
// cells must be blocked, every other kind must pass; a statement about a kind the run
// does not hold does not apply (neither met nor failed), and a run with no cells meets
// nothing.
struct ContractionPassageCheck {
  static constexpr double blocked_front_distance = 2.0;  // [μm]
  static constexpr double stalled_speed_fraction = 0.1;
  static constexpr double blocked_pressure_ratio = 2.0;
  std::vector<bool> passed;          // per cell, at the last row
  std::vector<bool> blocked;         // per cell, at the last row
  std::vector<double> passage_time;  // [s] per cell, the first row with it past the exit; −1: never
  std::vector<double> final_position;  // [μm] per cell, its centroid's x at the last row
  std::vector<double> front_before_hold;   // [μm] per cell, last row: what holds it (the throat's entry or
                                           // the rear of the nearest blocked cell ahead) minus the cell's
                                           // front (centroid + half its x-extent); negative beyond it
  std::vector<double> late_speed_ratio;    // per cell: its mean speed over the last quarter over that over
                                           // the first (infinite when it did not move forward at first)
  double end_time = 0.0;             // [s]
  double final_pressure_ratio = 0.0;  // relative_apparent_viscosity at the last row (0: no column)
  int normal_cells = 0;              // cells not of kind "sickle"
  int sickle_cells = 0;
  bool normal_cells_passed = false;  // there are normal cells and every one passed
  bool sickle_cells_blocked = false;  // there are sickle cells and every one is blocked
  bool met() const {
    return normal_cells + sickle_cells > 0 && (normal_cells == 0 || normal_cells_passed) &&
           (sickle_cells == 0 || sickle_cells_blocked);
  }
  // The numerics, apart from the paper's statement: the most compressed cell element's
  // J = det F over the run (column smallest_volume_ratio; 1 when the run has none). An
  // element below crushed_volume_ratio is crushed: squeezed by velocity gradients finer than
  // the fluid resolves, it is a step from inverting.
  static constexpr double crushed_volume_ratio = 0.2;
  double smallest_volume_ratio = 1.0;
  double smallest_volume_ratio_time = 0.0;  // [s] when it was reached
  bool no_element_crushed = true;
};
ContractionPassageCheck check_contraction_passage(const DiagnosticsRows& rows, const std::vector<std::string>& kinds,
                                                  double throat_entry, double throat_exit);

// Normal cells after the throat (Liu et al. 2004, Fig. 14: "they decelerate in the diffuser
// and pile up at the constriction's outlet"). The throat runs from x = `throat_entry` to
// `throat_exit`, the diffuser from there to `diffuser_exit` [μm]. For each cell not of kind
// "sickle": its mean speed along x while its centroid crosses the throat and while it
// crosses the diffuser (from the first row at or past a section's start to the first row
// past its end, or the last row; 0 when it never reached the section). A cell decelerates
// when it crossed both and its diffuser speed is below slower_fraction of its throat speed.
// Pile-up: at the first row where the last of these cells is past the throat's exit, the
// mean x-distance between neighbours (the cells sorted by x) over that at the first row;
// below closer_fraction the cells have piled up (infinite with fewer than two such cells or
// when they never all passed).
struct ContractionOutletCheck {
  static constexpr double slower_fraction = 0.9;
  static constexpr double closer_fraction = 0.9;
  std::vector<int> cells;               // the normal cells' indices
  std::vector<double> throat_speed;     // [μm/s] per normal cell
  std::vector<double> diffuser_speed;   // [μm/s] per normal cell
  double initial_spacing = 0.0;         // [μm] mean neighbour x-distance, first row
  double spacing_after = 0.0;           // [μm] the same when the last one has passed
  double spacing_ratio = INFINITY;      // spacing_after / initial_spacing
  double time_all_passed = -1.0;        // [s]; −1: never
};
ContractionOutletCheck check_contraction_outlet(const DiagnosticsRows& rows, const std::vector<std::string>& kinds,
                                                double throat_entry, double throat_exit, double diffuser_exit);

// A capsule squeezing through a capillary along x from `entry` to `exit` [μm] (Liu et
// al. 2004, Figs. 16-17): "the pressure rises while the capsule enters and plugs the
// capillary, stays up while it is inside and falls after it leaves; inside, the capsule is
// longer than its free diameter (a slug), and it leaves with its rear flared (a
// jellyfish)". Cell 0's centroid, x-extent and front and rear radii, and
// driving_pressure_Pa, over the run.
struct CapillaryPassageCheck {
  double initial_pressure = 0.0;  // [Pa] first row after step 0 (the capsule still in the inlet feeder)
  double peak_pressure = 0.0;     // [Pa] largest over the run
  double peak_position = 0.0;     // [μm] the capsule's centroid x at the peak
  double final_pressure = 0.0;    // [Pa] last row
  double final_position = 0.0;    // [μm] the capsule's centroid x, last row
  double free_length = 0.0;       // [μm] x-extent in the first row (undeformed)
  double longest_inside = 0.0;    // [μm] largest x-extent while the centroid is in [entry, exit]
  // The rows with the capsule wholly inside (its rear, centroid − extent/2, past `entry`,
  // its front before `exit`): how many, and the pressure's mean and spread (max − min)
  // over its mean there.
  int plateau_rows = 0;
  double plateau_mean = 0.0;                  // [Pa]
  double plateau_spread = INFINITY;
  // The rows with its rear out of the capillary by less than its free length (between
  // `exit` and exit + free_length): the largest R_rear / R_front (0: no such row).
  double largest_rear_over_front = 0.0;
  // Thresholds: the pressure rises when the peak is at least rise_fraction above the
  // initial pressure, with the capsule's centroid within a free diameter of the capillary;
  // it falls when the capsule's centroid is past `exit` + half its free length and the
  // pressure has come back by at least fall_fraction of the rise; longer when
  // longest_inside > free_length; a plateau when at least plateau_rows_min rows have it
  // wholly inside, with a spread of at most plateau_spread_max and a mean at least
  // rise_fraction above the initial pressure; flared when largest_rear_over_front reaches
  // flare_ratio.
  static constexpr double rise_fraction = 0.1;
  static constexpr double fall_fraction = 0.75;
  static constexpr int plateau_rows_min = 3;
  static constexpr double plateau_spread_max = 0.25;
  static constexpr double flare_ratio = 1.05;
  bool rose = false;
  bool left = false;
  bool fell = false;
  bool longer_inside = false;
  bool plateau = false;
  bool flared = false;
  bool met() const { return rose && left && fell && longer_inside && plateau && flared; }
};
CapillaryPassageCheck check_capillary_passage(const DiagnosticsRows& rows, double entry, double exit);

// Where the interaction acts (Liu et al. 2004, Fig. 7: "the interaction forces act mainly
// at the rims"), from the columns interaction_rim_share (the rim bands' share of the Morse
// forces' magnitude) and rim_area_share (their share of the surface; cells/rim_band.hpp).
// Met when, in every row where the forces act, the bands carry more than least_share of
// the force, at a force per area at least least_density_ratio times that over the rest
// of the surface. Not met when no row has forces.
struct RimInteractionCheck {
  static constexpr double least_share = 0.5;
  static constexpr double least_density_ratio = 2.0;
  double smallest_share = 0.0;       // over the rows with forces
  double smallest_share_time = 0.0;  // [s]
  double area_share = 0.0;
  double density_ratio = 0.0;        // (share / area share) / ((1 − share) / (1 − area share)), at the smallest share
  bool met = false;
};
RimInteractionCheck check_interaction_at_rims(const DiagnosticsRows& rows);

// Stacks of cells in simple shear (Liu et al. 2004, Figs. 7-12): columns of
// `cells_per_stack` cells each, cells 0, 1, ... stacked along y in that order within a
// column, columns one after the other; measured at the first and the last row. Neighbours
// are (i, i+1) within a column; the stack axis is the first column's.
struct StackMeasures {
  double largest_gap_growth = 0.0;         // [μm] max over neighbours of last − first gap_i_(i+1)
  double smallest_gap_growth = 0.0;        // [μm] min over neighbours of the same: above r0, no
                                           // neighbours are left together
  double largest_separation_change = 0.0;  // [μm] max over neighbours of |Δy_last − Δy_first| (centroids)
  double mean_inclination_deg = 0.0;       // last row: the cells' mean inclination in the shear plane
                                           // (0 = major axis along the flow)
  double inclination_spread_deg = 0.0;     // last row: the shortest arc holding every inclination,
                                           // modulo 180° (axes)
  double duration = 0.0;                   // [s] the last row's time_s minus the first's
  double stack_axis_deg = 0.0;             // last row: the first-to-last centroid line's angle from +y
                                           // toward +x. The shear (u = γ̇ y) turns a body clockwise: by θ,
                                           // the axis to +θ and the discs' inclination to −θ, so a stack
                                           // turning as one body keeps stack_axis ≈ −mean_inclination
  // The aggregate is intact while every neighbour gap has grown by less than r0.
  bool intact = false;
};

// Measures the run's first `cells` cells in columns of `cells_per_stack`; r0 [μm] for the
// intact test.
StackMeasures measure_stack(const DiagnosticsRows& rows, int cells, int cells_per_stack, double zero_force_length);

// The paper's statement (Liu et al. 2004, Figs. 8-12) for a stack's run, as measures
// against thresholds:
// - no interaction (Fig. 8): the cells keep their vertical separations (every change
//   < 0.5 μm);
// - shear rate ≤ 0.3 1/s (Fig. 9): the stack rotates as one body (intact: every gap grew by
//   less than r0; the centroid line turns with the discs, |axis + mean inclination| < 10°);
// - ≤ 1 1/s (Fig. 10): it aligns with the flow and starts to separate (a gap grew by more
//   than r0, out of the Morse well's range, the complement of "intact"; |mean inclination|
//   < 20°);
// - above, one column (Fig. 11): it breaks up completely into parallel layers (every
//   neighbour gap grew by more than r0, so no doublet is left; the inclinations agree
//   within 10°);
// - above, more than one column (Fig. 12): it partly breaks up and aligns in layers (a gap
//   grew by more than r0; the inclinations agree within 10°).
// Each holds over the paper's duration, so the run must have sheared at least as long:
// its strain (shear rate × duration) at least the paper's — Figs. 8 and 9 to 4 s at
// 0.25 1/s (strain 1), Fig. 10 to 1 s at 0.5 1/s (0.5), Fig. 11 to 0.5 s at 3 1/s (1.5),
// Fig. 12 to 3 s at 3 1/s (9). A shorter run meets nothing.
struct StackStatement {
  std::string figure;      // "Fig. 9"
  std::string statement;   // the paper's words
  double strain = 0.0;     // the run's: shear rate × duration
  double required_strain = 0.0;  // the paper's
  bool long_enough = false;
  std::vector<PaperMeasure> measures;  // the strain against the paper's, then each measure of the statement
  std::string measured;    // the measures' text, joined by ", "
  bool met = false;        // long enough, and every measure within its threshold
};
StackStatement check_stack_statement(const StackMeasures& measures, double shear_rate, bool interaction,
                                     double zero_force_length, int columns = 1);

}  // namespace rouleau
