// The scene checks of src/analysis/scene_checks.hpp on made-up diagnostics whose measures
// are known: a four-cell stack at its first and last rows, and the paper's statements
// (Liu et al. 2004, Figs. 7-12) on either side of each threshold.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "analysis/scene_checks.hpp"
#include "capillary_passage_rows.hpp"
#include "throat_passage_rows.hpp"

namespace {

using rouleau::DiagnosticsRows;

// A row of a vertical stack at `time`: cell c at (x[c], y[c]) with inclination incl,
// neighbour gaps gap[c].
std::map<std::string, double> stack_row(const double (&x)[4], const double (&y)[4], double inclination,
                                        const double (&gap)[3], double time) {
  std::map<std::string, double> row{{"time_s", time}};
  for (int c = 0; c < 4; ++c) {
    const std::string cell = "cell" + std::to_string(c) + "_";
    row[cell + "centroid_x_um"] = x[c];
    row[cell + "centroid_y_um"] = y[c];
    row[cell + "inclination_deg"] = inclination + c;  // spread 3 deg
  }
  for (int c = 0; c < 3; ++c) row["gap_" + std::to_string(c) + "_" + std::to_string(c + 1) + "_um"] = gap[c];
  return row;
}

TEST(SceneChecks, StackMeasuresAreTheChangesBetweenTheFirstAndLastRows) {
  const DiagnosticsRows rows{stack_row({0, 0, 0, 0}, {-6, -2, 2, 6}, 0.0, {1.4, 1.4, 1.4}, 0.5),
                             stack_row({-1, 0, 0, 1}, {-6.5, -2, 2.3, 6}, -12.0, {1.0, 2.1, 1.3}, 4.5)};
  const auto m = rouleau::measure_stack(rows, 4, 4, 0.25);
  EXPECT_NEAR(m.largest_gap_growth, 0.7, 1e-12);          // the middle gap, 1.4 -> 2.1
  EXPECT_NEAR(m.smallest_gap_growth, -0.4, 1e-12);        // the lower gap, 1.4 -> 1.0
  EXPECT_NEAR(m.largest_separation_change, 0.5, 1e-12);   // cells 0-1: 4 -> 4.5
  EXPECT_NEAR(m.mean_inclination_deg, -10.5, 1e-12);      // -12, -11, -10, -9
  EXPECT_NEAR(m.inclination_spread_deg, 3.0, 1e-12);
  EXPECT_NEAR(m.stack_axis_deg, std::atan2(2.0, 12.5) * 180.0 / M_PI, 1e-12);  // dx 2, dy 12.5
  EXPECT_NEAR(m.duration, 4.0, 1e-12);                    // 0.5 s -> 4.5 s
  EXPECT_FALSE(m.intact);                                 // 0.7 > r0
  // Inclinations are axes: discs at −89.9, +86.7, +87.1 and −89.6 deg (all near the
  // vertical) lie within 3.7 deg of each other, their mean axis at −91.425 deg, that is
  // +88.575 (the doubled-angle mean departs from the plain one by 1e-4 deg here).
  DiagnosticsRows upright = rows;
  const double across[4] = {-89.9, 86.7, 87.1, -89.6};
  for (int c = 0; c < 4; ++c) upright.back()["cell" + std::to_string(c) + "_inclination_deg"] = across[c];
  const auto u = rouleau::measure_stack(upright, 4, 4, 0.25);
  EXPECT_NEAR(u.inclination_spread_deg, 3.7, 1e-9);
  EXPECT_NEAR(u.mean_inclination_deg, 88.575, 0.01);
}

TEST(SceneChecks, EachShearRateHasThePapersStatementWithItsThresholds) {
  rouleau::StackMeasures held;  // a stack turned by 20 deg as one body, gaps grown by 0.1 um, over 8 s
  held.largest_gap_growth = 0.1;
  held.intact = true;
  held.mean_inclination_deg = -20.0;
  held.stack_axis_deg = 18.0;
  held.inclination_spread_deg = 2.0;
  held.duration = 8.0;
  rouleau::StackMeasures parted = held;  // the same with every gap grown by 0.4 um or more
  parted.largest_gap_growth = 0.6;
  parted.smallest_gap_growth = 0.4;
  parted.intact = false;
  const double r0 = 0.25;
  const auto rotates = rouleau::check_stack_statement(held, 0.25, true, r0);
  EXPECT_EQ(rotates.figure, "Fig. 9");
  EXPECT_TRUE(rotates.met) << rotates.measured;
  EXPECT_FALSE(rouleau::check_stack_statement(parted, 0.25, true, r0).met);
  rouleau::StackMeasures sliding = held;  // intact but the centroid line does not turn with the discs
  sliding.stack_axis_deg = 0.0;
  EXPECT_FALSE(rouleau::check_stack_statement(sliding, 0.25, true, r0).met);
  // Held, but only for 20 ms: shorter than the paper's 4 s at 0.25 1/s (strain 1), so not met.
  rouleau::StackMeasures brief = held;
  brief.duration = 0.02;
  const auto too_short = rouleau::check_stack_statement(brief, 0.25, true, r0);
  EXPECT_FALSE(too_short.long_enough);
  EXPECT_FALSE(too_short.met);
  EXPECT_NEAR(too_short.strain, 0.005, 1e-12);
  brief.duration = 4.0;  // exactly the paper's
  EXPECT_TRUE(rouleau::check_stack_statement(brief, 0.25, true, r0).met);
  // 0.5 1/s: starting to separate is the complement of intact; aligned within 20 deg.
  EXPECT_FALSE(rouleau::check_stack_statement(held, 0.5, true, r0).met);
  rouleau::StackMeasures aligned_parted = parted;
  aligned_parted.mean_inclination_deg = -8.0;
  EXPECT_TRUE(rouleau::check_stack_statement(aligned_parted, 0.5, true, r0).met);
  EXPECT_FALSE(rouleau::check_stack_statement(parted, 0.5, true, r0).met);  // -20 deg: not aligned
  // 3.0 1/s: apart and in parallel layers (Fig. 11 to 0.5 s; Fig. 12, two columns, to 3 s).
  const auto layers = rouleau::check_stack_statement(parted, 3.0, true, r0);
  EXPECT_EQ(layers.figure, "Fig. 11");
  EXPECT_TRUE(layers.met);
  rouleau::StackMeasures tumbling = parted;
  tumbling.inclination_spread_deg = 25.0;
  EXPECT_FALSE(rouleau::check_stack_statement(tumbling, 3.0, true, r0).met);
  // Two doublets sliding apart as parallel layers (the middle gap grown 3.5 um, the outer
  // ones closed by 0.05): not a complete break-up (Fig. 11), but a partial one (Fig. 12).
  rouleau::StackMeasures doublets = parted;
  doublets.largest_gap_growth = 3.5;
  doublets.smallest_gap_growth = -0.05;
  const auto two_doublets = rouleau::check_stack_statement(doublets, 3.0, true, r0);
  EXPECT_FALSE(two_doublets.met);
  EXPECT_NE(two_doublets.measured.find("smallest gap growth (threshold r0) -0.0500 > 0.25 um: NO"), std::string::npos)
      << two_doublets.measured;
  doublets.duration = 3.0;  // strain 9, the paper's twelve cells'
  EXPECT_TRUE(rouleau::check_stack_statement(doublets, 3.0, true, r0, 3).met);
  rouleau::StackMeasures twelve = parted;
  twelve.duration = 2.0;  // strain 6, the paper's twelve cells sheared to 9
  const auto aggregate = rouleau::check_stack_statement(twelve, 3.0, true, r0, 3);
  EXPECT_EQ(aggregate.figure, "Fig. 12");
  EXPECT_FALSE(aggregate.met);
  EXPECT_TRUE(rouleau::check_stack_statement(twelve, 3.0, true, r0, 1).met);  // one column: Fig. 11, strain 1.5
  // Each measure is printed with the relation it was held to and whether it holds: gaps
  // that closed by 0.88 um at 3.0 1/s read "-0.8800 > 0.25 um: NO".
  rouleau::StackMeasures closed = parted;
  closed.largest_gap_growth = -0.5;
  closed.smallest_gap_growth = -0.88;
  closed.intact = true;
  const auto not_apart = rouleau::check_stack_statement(closed, 3.0, true, r0);
  EXPECT_FALSE(not_apart.met);
  EXPECT_NE(not_apart.measured.find("smallest gap growth (threshold r0) -0.8800 > 0.25 um: NO"), std::string::npos)
      << not_apart.measured;
  EXPECT_NE(not_apart.measured.find("inclination spread 2.0000 < 10 deg: yes"), std::string::npos)
      << not_apart.measured;
  // Without the interaction, whatever the rate: the vertical separations (Fig. 8).
  held.largest_separation_change = 0.3;
  EXPECT_TRUE(rouleau::check_stack_statement(held, 3.0, false, r0).met);
  held.largest_separation_change = 0.9;
  const auto moved = rouleau::check_stack_statement(held, 3.0, false, r0);
  EXPECT_EQ(moved.figure, "Fig. 8");
  EXPECT_FALSE(moved.met);
  EXPECT_NE(moved.measured.find("0.9000"), std::string::npos) << moved.measured;
}

// A capsule row: centroid x, x-extent, driving pressure.

TEST(SceneChecks, ContractionPassageWantsNormalCellsThroughAndSickleCellsHeld) {
  // Two cells (x-extent 8 um) and a throat from x = 30 to 40 um, five rows 1 s apart: cell
  // 0 passes at 3 s; cell 1 reaches the entrance (front at 29.5 um) and stalls there
  // (speed 5 um/s in the first quarter, 0.2 um/s in the last).
  DiagnosticsRows rows = rouleau::testing::throat_passage_rows();
  const auto normal = rouleau::check_contraction_passage(rows, {"normal", "normal"}, 30.0, 40.0);
  EXPECT_TRUE(normal.passed[0]);
  EXPECT_FALSE(normal.passed[1]);
  EXPECT_FALSE(normal.blocked[0]);
  EXPECT_TRUE(normal.blocked[1]);
  EXPECT_DOUBLE_EQ(normal.passage_time[0], 3.0);
  EXPECT_DOUBLE_EQ(normal.passage_time[1], -1.0);
  EXPECT_DOUBLE_EQ(normal.final_position[1], 25.5);
  EXPECT_DOUBLE_EQ(normal.end_time, 4.0);
  EXPECT_EQ(normal.normal_cells, 2);
  EXPECT_FALSE(normal.met());  // a normal cell held at the entrance
  // The held cell a sickle cell: the statement holds; the passing one a sickle cell: not.
  EXPECT_TRUE(rouleau::check_contraction_passage(rows, {"normal", "sickle"}, 30.0, 40.0).met());
  const auto wrong = rouleau::check_contraction_passage(rows, {"sickle", "sickle"}, 30.0, 40.0);
  EXPECT_FALSE(wrong.sickle_cells_blocked);
  EXPECT_FALSE(wrong.normal_cells_passed);  // there are none: the statement about them does not apply
  EXPECT_EQ(wrong.normal_cells, 0);
  EXPECT_FALSE(wrong.met());
  // Only a sickle cell, the stalled one as cell 0: met by the sickle statement alone.
  DiagnosticsRows stalled = rows;
  for (auto& row : stalled) row["cell0_centroid_x_um"] = row["cell1_centroid_x_um"];
  EXPECT_TRUE(rouleau::check_contraction_passage(stalled, {"sickle"}, 30.0, 40.0).met());
  // A sickle cell that stops short of the entrance (with the entry at 32 um its front, at
  // 29.5 um, is 2.5 um short), or a run that ends while it still moves (the first three
  // rows: 10 um/s to the end), shows no blockage.
  const DiagnosticsRows early(rows.begin(), rows.begin() + 3);
  EXPECT_FALSE(rouleau::check_contraction_passage(rows, {"normal", "sickle"}, 32.0, 40.0).met());
  EXPECT_FALSE(rouleau::check_contraction_passage(early, {"sickle", "sickle"}, 30.0, 50.0).met());
  // No cells: nothing is met.
  EXPECT_FALSE(rouleau::check_contraction_passage(rows, {}, 30.0, 40.0).met());
  // Stalled at the entrance but the flow not held back (the driving pressure 1.5 times
  // Hagen-Poiseuille's at the end, below 2): the cell does not block the throat.
  DiagnosticsRows flowing = stalled;
  flowing.back()["relative_apparent_viscosity"] = 1.5;
  const auto open = rouleau::check_contraction_passage(flowing, {"sickle"}, 30.0, 40.0);
  EXPECT_TRUE(open.blocked[0]);
  EXPECT_FALSE(open.sickle_cells_blocked);
  // A queue: a third cell stalled behind the held one (its front 1 um behind that cell's
  // rear at 21.5 um) is blocked too; 3 um behind it is not, nor is one stalled far back.
  DiagnosticsRows queue = rows;
  const double x2[5] = {5, 10, 15, 16.4, 16.5};  // front at 20.5 um at the end
  for (int r = 0; r < 5; ++r) {
    queue[r]["cell2_centroid_x_um"] = x2[r];
    queue[r]["cell2_extent_x_um"] = 8.0;
  }
  const auto queued = rouleau::check_contraction_passage(queue, {"normal", "sickle", "sickle"}, 30.0, 40.0);
  EXPECT_DOUBLE_EQ(queued.front_before_hold[2], 1.0);
  EXPECT_TRUE(queued.blocked[2]);
  EXPECT_TRUE(queued.met());
  for (auto& row : queue) row["cell2_centroid_x_um"] -= 2.0;
  const auto gap = rouleau::check_contraction_passage(queue, {"normal", "sickle", "sickle"}, 30.0, 40.0);
  EXPECT_DOUBLE_EQ(gap.front_before_hold[2], 3.0);
  EXPECT_FALSE(gap.blocked[2]);
  EXPECT_FALSE(gap.met());
  // Without the elements' column nothing is known to be crushed; with it, the smallest J
  // and when, and an element at J = 0.15 is crushed (0.25 is not).
  EXPECT_TRUE(normal.no_element_crushed);
  const double volume_ratio[5] = {1.0, 0.15, 0.4, 0.5, 0.5};
  for (int r = 0; r < 5; ++r) rows[r]["smallest_volume_ratio"] = volume_ratio[r];
  const auto crushed = rouleau::check_contraction_passage(rows, {"normal", "normal"}, 30.0, 40.0);
  EXPECT_DOUBLE_EQ(crushed.smallest_volume_ratio, 0.15);
  EXPECT_DOUBLE_EQ(crushed.smallest_volume_ratio_time, 1.0);
  EXPECT_FALSE(crushed.no_element_crushed);
  rows[1]["smallest_volume_ratio"] = 0.25;
  EXPECT_TRUE(rouleau::check_contraction_passage(rows, {"normal", "normal"}, 30.0, 40.0).no_element_crushed);
}

TEST(SceneChecks, ContractionOutletWantsCellsSlowerInTheDiffuserAndCloserAfterIt) {
  // A throat from x = 30 to 40 um, a diffuser to 50 um; seven rows 1 s apart. Cells 0 and 1
  // start 5 um apart; cell 2, a sickle cell, stays behind and does not count.
  auto rows_of = [](const std::vector<double>& x0, const std::vector<double>& x1) {
    DiagnosticsRows rows;
    for (std::size_t r = 0; r < x0.size(); ++r)
      rows.push_back({{"time_s", double(r)},
                      {"cell0_centroid_x_um", x0[r]},
                      {"cell1_centroid_x_um", x1[r]},
                      {"cell2_centroid_x_um", 0.0}});
    return rows;
  };
  const std::vector<std::string> kinds{"normal", "normal", "sickle"};
  // Cell 0 crosses the throat from 30 (t = 2) to 45 (t = 4): 7.5 um/s; the diffuser from 40
  // (t = 3) to 55 (t = 6): 5 um/s. Cell 1: 8 and 5 um/s. Both past 40 um first at t = 5,
  // 50 and 41 um: 9 um apart against 5 at the start, not piled up.
  const auto apart = rouleau::check_contraction_outlet(rows_of({10, 20, 30, 40, 45, 50, 55}, {5, 12, 19, 26, 33, 41, 46}),
                                                       kinds, 30.0, 40.0, 50.0);
  ASSERT_EQ(apart.cells.size(), 2u);
  EXPECT_DOUBLE_EQ(apart.throat_speed[0], 7.5);
  EXPECT_DOUBLE_EQ(apart.diffuser_speed[0], 5.0);
  EXPECT_DOUBLE_EQ(apart.throat_speed[1], 8.0);
  EXPECT_DOUBLE_EQ(apart.diffuser_speed[1], 5.0);
  EXPECT_DOUBLE_EQ(apart.initial_spacing, 5.0);
  EXPECT_DOUBLE_EQ(apart.time_all_passed, 5.0);
  EXPECT_DOUBLE_EQ(apart.spacing_ratio, 9.0 / 5.0);
  // Cell 0 nearly stops after the diffuser and cell 1 catches up: 3 um apart at t = 5.
  const auto piled = rouleau::check_contraction_outlet(rows_of({10, 20, 30, 40, 44, 46, 47}, {5, 12, 19, 28, 36, 43, 47}),
                                                       kinds, 30.0, 40.0, 50.0);
  EXPECT_DOUBLE_EQ(piled.spacing_ratio, 3.0 / 5.0);
  EXPECT_NEAR(piled.diffuser_speed[0], 7.0 / 3.0, 1e-12);  // 40 -> 47 over 3 s (never past 50)
  // A cell that never reached the throat has no speed there, and nobody passed: no spacing.
  const auto held = rouleau::check_contraction_outlet(rows_of({10, 20, 30, 40, 45, 50, 55}, {5, 6, 7, 8, 9, 10, 11}),
                                                      kinds, 30.0, 40.0, 50.0);
  EXPECT_DOUBLE_EQ(held.throat_speed[1], 0.0);
  EXPECT_DOUBLE_EQ(held.time_all_passed, -1.0);
  EXPECT_TRUE(std::isinf(held.spacing_ratio));
}

TEST(SceneChecks, CapillaryPassageRisesPlugsStretchesAndFalls) {
  using rouleau::testing::capsule_row;
  const DiagnosticsRows passage = rouleau::testing::capillary_passage_rows();
  const auto c = rouleau::check_capillary_passage(passage, 20.0, 40.0);
  EXPECT_DOUBLE_EQ(c.peak_pressure, 4.0);
  EXPECT_DOUBLE_EQ(c.peak_position, 30.0);
  EXPECT_DOUBLE_EQ(c.longest_inside, 9.0);
  EXPECT_DOUBLE_EQ(c.free_length, 6.0);
  EXPECT_EQ(c.plateau_rows, 3);
  EXPECT_DOUBLE_EQ(c.plateau_mean, 3.8);
  EXPECT_NEAR(c.plateau_spread, 0.4 / 3.8, 1e-12);
  EXPECT_NEAR(c.largest_rear_over_front, 1.1, 1e-12);
  EXPECT_TRUE(c.rose && c.left && c.fell && c.longer_inside && c.plateau && c.flared);
  EXPECT_TRUE(c.met());
  // A peak without a plateau: inside, the pressure swings by half its mean.
  DiagnosticsRows swinging = passage;
  swinging[2] = capsule_row(26, 9.0, 2.6);
  swinging[4] = capsule_row(34, 9.0, 2.5);
  const auto w = rouleau::check_capillary_passage(swinging, 20.0, 40.0);
  EXPECT_GT(w.plateau_spread, rouleau::CapillaryPassageCheck::plateau_spread_max);
  EXPECT_FALSE(w.plateau);
  EXPECT_FALSE(w.met());
  // A capsule that leaves round (rear 3.05 against front 3.0, below 1.05) is no jellyfish;
  // nor is one whose rear flares only once it is far past the exit (rear at 48.5).
  DiagnosticsRows round = passage;
  round[6] = capsule_row(45.5, 7.0, 2.2, 3.05, 3.0);
  EXPECT_FALSE(rouleau::check_capillary_passage(round, 20.0, 40.0).flared);
  DiagnosticsRows late = passage;
  late[6] = capsule_row(45.5, 7.0, 2.2, 3.0, 3.0);
  late[7] = capsule_row(52.0, 7.0, 1.8, 3.3, 3.0);
  EXPECT_FALSE(rouleau::check_capillary_passage(late, 20.0, 40.0).flared);
  // Still inside at the end: it has not left, so the pressure has not fallen.
  const DiagnosticsRows stuck(passage.begin(), passage.begin() + 4);
  const auto s = rouleau::check_capillary_passage(stuck, 20.0, 40.0);
  EXPECT_TRUE(s.rose);
  EXPECT_FALSE(s.left);
  EXPECT_FALSE(s.fell);
  EXPECT_FALSE(s.met());
  // Left, but the pressure stayed up (fallen by 0.6 of the 2.4 Pa rise, below 3/4).
  DiagnosticsRows high = passage;
  high.back() = capsule_row(50, 6.5, 3.4);
  EXPECT_FALSE(rouleau::check_capillary_passage(high, 20.0, 40.0).fell);
  // A 5 % rise is no rise; a capsule that kept its length inside is not "longer".
  const DiagnosticsRows flat{capsule_row(7, 6.0, 1.6), capsule_row(30, 6.0, 1.68), capsule_row(50, 6.0, 1.6)};
  const auto f = rouleau::check_capillary_passage(flat, 20.0, 40.0);
  EXPECT_FALSE(f.rose);
  EXPECT_FALSE(f.longer_inside);
  // The row of step 0 (the fluid at rest, no driving pressure yet) is no start to rise from.
  DiagnosticsRows from_rest = flat;
  for (std::size_t r = 0; r < from_rest.size(); ++r) from_rest[r]["step"] = 10.0 * r + 10.0;
  auto at_rest = capsule_row(7, 6.0, 0.0);
  at_rest["step"] = 0.0;
  from_rest.insert(from_rest.begin(), at_rest);
  const auto r = rouleau::check_capillary_passage(from_rest, 20.0, 40.0);
  EXPECT_DOUBLE_EQ(r.initial_pressure, 1.6);
  EXPECT_FALSE(r.rose);
}

TEST(SceneChecks, InteractionMainlyAtTheRimsWantsMostOfTheForceAtTwiceTheDensity) {
  // Rows of (share, area share): the row with no force (share 0) is left out.
  auto rows_of = [](std::vector<double> shares, double area_share) {
    rouleau::DiagnosticsRows rows;
    for (std::size_t r = 0; r < shares.size(); ++r)
      rows.push_back({{"time_s", 0.01 * r}, {"interaction_rim_share", shares[r]}, {"rim_area_share", area_share}});
    return rows;
  };
  const auto met = rouleau::check_interaction_at_rims(rows_of({0.0, 0.91, 0.88, 0.9}, 0.48));
  EXPECT_TRUE(met.met);
  EXPECT_DOUBLE_EQ(met.smallest_share, 0.88);
  EXPECT_DOUBLE_EQ(met.smallest_share_time, 0.02);
  EXPECT_NEAR(met.density_ratio, (0.88 / 0.48) / (0.12 / 0.52), 1e-12);
  // Less than half the force in the bands at one row: not met.
  EXPECT_FALSE(rouleau::check_interaction_at_rims(rows_of({0.9, 0.45, 0.9}, 0.3)).met);
  // Most of the force, but the bands most of the surface: density ratio 1.23 < 2.
  const auto spread = rouleau::check_interaction_at_rims(rows_of({0.6}, 0.55));
  EXPECT_FALSE(spread.met);
  EXPECT_NEAR(spread.density_ratio, (0.6 / 0.55) / (0.4 / 0.45), 1e-12);
  // No force at all: nothing shown.
  EXPECT_FALSE(rouleau::check_interaction_at_rims(rows_of({0.0, 0.0}, 0.48)).met);
}

}  // namespace
