// The paper's statements as rows (src/analysis/paper_checks.hpp): each measure held to its
// relation on both sides of its threshold, and for every scene's check the rows all met
// exactly when the check is met, on made-up diagnostics; the CSV a driver writes.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/paper_checks.hpp"
#include "capillary_passage_rows.hpp"
#include "temporary_folder.hpp"
#include "throat_passage_rows.hpp"

namespace {

using rouleau::DiagnosticsRows;
using rouleau::PaperCheckRow;

bool all_met(const std::vector<PaperCheckRow>& rows) {
  bool met = !rows.empty();
  for (const auto& row : rows) met = met && row.measure.met;
  return met;
}

TEST(PaperChecks, AMeasureHoldsByItsRelationAndSaysSo) {
  EXPECT_TRUE(rouleau::measure_against("gap", 0.2, "<", 0.25, "um").met);
  EXPECT_FALSE(rouleau::measure_against("gap", 0.25, "<", 0.25, "um").met);
  EXPECT_TRUE(rouleau::measure_against("gap", 0.25, "<=", 0.25, "um").met);
  EXPECT_FALSE(rouleau::measure_against("gap", 0.3, "<=", 0.25, "um").met);
  EXPECT_TRUE(rouleau::measure_against("strain", 1.0, ">=", 1.0, "").met);
  EXPECT_FALSE(rouleau::measure_against("strain", 1.0, ">", 1.0, "").met);
  EXPECT_FALSE(rouleau::measure_against("strain", 0.99, ">=", 1.0, "").met);
  EXPECT_EQ(rouleau::measure_against("largest gap growth", -0.88, ">", 0.25, "um (r0)").text(),
            "largest gap growth -0.8800 > 0.25 um (r0): NO");
  EXPECT_EQ(rouleau::measure_against("share", 0.9, ">", 0.5, "").text(), "share 0.9000 > 0.5: yes");
  EXPECT_THROW(rouleau::measure_against("gap", 0.2, "=", 0.25, "um"), std::invalid_argument);
}

TEST(PaperChecks, AggregationRowsAreMetExactlyWhenTheGapClosedAndSettled) {
  const double r0 = 0.25;
  rouleau::AggregationCheck check;
  check.final_gap = 0.0958;
  check.settled_gap_range = 0.01;
  check.closed = check.settled = true;
  const auto rows = rouleau::paper_rows(check, r0, true);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].figure, "Fig. 6");
  EXPECT_DOUBLE_EQ(rows[0].measure.threshold, 0.375);
  EXPECT_DOUBLE_EQ(rows[1].measure.threshold, 0.05);
  EXPECT_TRUE(all_met(rows));
  check.final_gap = 0.4;  // not closed
  EXPECT_FALSE(all_met(rouleau::paper_rows(check, r0, true)));
  check.final_gap = 0.0958;
  check.settled_gap_range = 0.06;  // still moving
  EXPECT_FALSE(all_met(rouleau::paper_rows(check, r0, true)));
  // Without the interaction the run is the scene's control: no statement of the paper.
  EXPECT_TRUE(rouleau::paper_rows(check, r0, false).empty());
}

TEST(PaperChecks, StackRowsAreTheStatementsMeasuresWithTheStrainFirst) {
  rouleau::StackMeasures held;  // turned by 20 deg as one body, gaps grown by 0.1 um, over 4 s
  held.largest_gap_growth = 0.1;
  held.mean_inclination_deg = -20.0;
  held.stack_axis_deg = 18.0;
  held.duration = 4.0;
  const auto met = rouleau::check_stack_statement(held, 0.25, true, 0.25);
  const auto rows = rouleau::paper_rows(met);
  ASSERT_EQ(rows.size(), 3u);  // strain, gap growth, |axis + inclination|
  EXPECT_EQ(rows[0].measure.metric, "strain (threshold: the paper's)");
  EXPECT_DOUBLE_EQ(rows[0].measure.threshold, 1.0);
  for (const auto& row : rows) EXPECT_EQ(row.figure, "Fig. 9");
  EXPECT_TRUE(met.met);
  EXPECT_TRUE(all_met(rows));
  // Sheared for 3.9 s of the paper's 4: the strain's row fails, and so does the statement.
  held.duration = 3.9;
  const auto short_run = rouleau::check_stack_statement(held, 0.25, true, 0.25);
  EXPECT_FALSE(short_run.met);
  EXPECT_FALSE(rouleau::paper_rows(short_run)[0].measure.met);
  EXPECT_TRUE(rouleau::paper_rows(short_run)[1].measure.met);
  // The last row's time 1e-9 s short of 4 s (round-off in the time sum) is the paper's strain.
  held.duration = 4.0 - 1e-9;
  EXPECT_TRUE(rouleau::check_stack_statement(held, 0.25, true, 0.25).long_enough);
}

TEST(PaperChecks, ContractionRowsFollowTheCellsKinds) {
  // A throat from x = 30 to 40 um; cell 0 passes, cell 1 stalls with its front 0.5 um
  // before the entry.
  const DiagnosticsRows rows = rouleau::testing::throat_passage_rows();
  for (const std::vector<std::string>& kinds : std::vector<std::vector<std::string>>{
           {"normal", "sickle"}, {"normal", "normal"}, {"sickle", "sickle"}, {"sickle", "normal"}}) {
    const auto check = rouleau::check_contraction_passage(rows, kinds, 30.0, 40.0);
    const auto paper = rouleau::paper_rows(check, kinds, 40.0);
    std::vector<PaperCheckRow> fig14, fig15;
    for (const auto& row : paper) (row.figure == "Fig. 14" ? fig14 : fig15).push_back(row);
    EXPECT_EQ(all_met(fig14), check.normal_cells_passed) << kinds[0] << " " << kinds[1];
    EXPECT_EQ(all_met(fig15), check.sickle_cells_blocked) << kinds[0] << " " << kinds[1];
    EXPECT_EQ(fig14.size(), static_cast<std::size_t>(check.normal_cells));
    EXPECT_EQ(fig15.size(), 3u * check.sickle_cells + (check.sickle_cells > 0 ? 1u : 0u));
  }
  const std::vector<std::string> kinds{"normal", "sickle"};
  const auto check = rouleau::check_contraction_passage(rows, kinds, 30.0, 40.0);
  const auto paper = rouleau::paper_rows(check, kinds, 40.0);
  ASSERT_EQ(paper.size(), 5u);
  EXPECT_DOUBLE_EQ(paper[0].measure.value, 55.0);
  EXPECT_DOUBLE_EQ(paper[2].measure.value, 0.5);               // 30 − (25.5 + 4)
  EXPECT_NEAR(paper[3].measure.value, 0.2 / 5.0, 1e-12);      // late over early speed
  EXPECT_DOUBLE_EQ(paper[4].measure.value, 3.0);               // the pressure ratio at the end
  EXPECT_TRUE(all_met(paper));
  // The flow no longer held back at the end (the ratio back to 1.5): no blockage.
  DiagnosticsRows flowing = rows;
  flowing.back()["relative_apparent_viscosity"] = 1.5;
  const auto open = rouleau::check_contraction_passage(flowing, kinds, 30.0, 40.0);
  EXPECT_FALSE(open.sickle_cells_blocked);
  EXPECT_FALSE(all_met(rouleau::paper_rows(open, kinds, 40.0)));
}

TEST(PaperChecks, OutletRowsWantEveryCellSlowerAndThemCloser) {
  rouleau::ContractionOutletCheck check;
  check.cells = {0, 1};
  check.throat_speed = {7.5, 8.0};
  check.diffuser_speed = {5.0, 5.0};
  check.spacing_ratio = 0.6;
  auto rows = rouleau::paper_rows(check);
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) EXPECT_EQ(row.figure, "Fig. 14");
  EXPECT_NEAR(rows[0].measure.value, 5.0 / 7.5, 1e-12);
  EXPECT_TRUE(all_met(rows));
  check.spacing_ratio = 1.8;  // not piled up
  EXPECT_FALSE(all_met(rouleau::paper_rows(check)));
  check.spacing_ratio = 0.6;
  check.diffuser_speed[1] = 7.5;  // 7.5 / 8 = 0.94: not slower by a tenth
  EXPECT_FALSE(all_met(rouleau::paper_rows(check)));
  check.throat_speed[1] = 0.0;  // never crossed the throat
  EXPECT_FALSE(rouleau::paper_rows(check)[1].measure.met);
  // One normal cell: no spacing to measure, no row for it.
  check.cells = {0};
  check.throat_speed = {7.5};
  check.diffuser_speed = {5.0};
  EXPECT_EQ(rouleau::paper_rows(check).size(), 1u);
}

TEST(PaperChecks, CapillaryRowsAreMetExactlyWhenThePassageIs) {
  using rouleau::testing::capsule_row;
  const DiagnosticsRows passage = rouleau::testing::capillary_passage_rows();
  DiagnosticsRows high = passage;
  high.back() = capsule_row(50, 6.5, 3.4);  // left, the pressure still up
  const DiagnosticsRows stuck(passage.begin(), passage.begin() + 4);
  DiagnosticsRows round = passage;  // leaves with its rear no wider than its front
  round[6] = capsule_row(45.5, 7.0, 2.2, 3.0, 3.0);
  DiagnosticsRows swinging = passage;  // inside, the pressure swings by half its mean
  swinging[2] = capsule_row(26, 9.0, 2.6);
  swinging[4] = capsule_row(34, 9.0, 2.5);
  const DiagnosticsRows flat{capsule_row(7, 6.0, 1.6), capsule_row(30, 6.0, 1.68), capsule_row(50, 6.0, 1.6)};
  DiagnosticsRows far_peak = passage;  // the peak with the capsule 10 um before the capillary
  far_peak[0] = capsule_row(2, 6.0, 1.6);
  far_peak[1] = capsule_row(10, 6.4, 5.0);
  const std::vector<const DiagnosticsRows*> cases{&passage, &high, &stuck, &flat, &far_peak, &round, &swinging};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto check = rouleau::check_capillary_passage(*cases[i], 20.0, 40.0);
    const auto paper = rouleau::paper_rows(check, 20.0, 40.0);
    ASSERT_EQ(paper.size(), 9u);
    EXPECT_EQ(paper[0].figure, "Fig. 16");
    EXPECT_EQ(paper[1].figure, "Fig. 16");
    const std::vector<PaperCheckRow> fig16(paper.begin(), paper.begin() + 2), fig17(paper.begin() + 2, paper.end());
    EXPECT_EQ(all_met(fig16), check.longer_inside && check.flared) << "case " << i;
    EXPECT_EQ(all_met(fig17), check.rose && check.left && check.fell && check.plateau) << "case " << i;
  }
  EXPECT_FALSE(all_met(rouleau::paper_rows(rouleau::check_capillary_passage(round, 20.0, 40.0), 20.0, 40.0)));
  EXPECT_FALSE(all_met(rouleau::paper_rows(rouleau::check_capillary_passage(swinging, 20.0, 40.0), 20.0, 40.0)));
  EXPECT_TRUE(all_met(rouleau::paper_rows(rouleau::check_capillary_passage(passage, 20.0, 40.0), 20.0, 40.0)));
  EXPECT_FALSE(all_met(rouleau::paper_rows(rouleau::check_capillary_passage(far_peak, 20.0, 40.0), 20.0, 40.0)));
}

TEST(PaperChecks, RimRowsOnlyWhenTheForcesActed) {
  rouleau::RimInteractionCheck check;
  check.smallest_share = 0.88;
  check.density_ratio = 7.9;
  check.met = true;
  EXPECT_TRUE(all_met(rouleau::paper_rows(check, true)));
  check.density_ratio = 1.2;
  EXPECT_FALSE(all_met(rouleau::paper_rows(check, true)));
  EXPECT_TRUE(rouleau::paper_rows(check, false).empty());
}

TEST(PaperChecks, TheCsvQuotesItsTextAndTheDriversFileIsWhole) {
  const std::vector<PaperCheckRow> rows{
      {"Fig. 9", "0.25 1/s: the stack rotates as one \"body\", intact",
       rouleau::measure_against("largest gap growth", 0.125, "<", 0.25, "um (r0)")},
      {"Fig. 9", "0.25 1/s", rouleau::measure_against("strain", 0.5, ">=", 1.0, "")}};
  const std::string csv = rouleau::paper_checks_csv(rows);
  EXPECT_EQ(csv,
            "figure,statement,metric,value,relation,threshold,unit,met\n"
            "\"Fig. 9\",\"0.25 1/s: the stack rotates as one \"\"body\"\", intact\",\"largest gap growth\",0.125,"
            "\"<\",0.25,\"um (r0)\",1\n"
            "\"Fig. 9\",\"0.25 1/s\",\"strain\",0.5,\">=\",1,\"\",0\n");
  const auto folder = rouleau::testing::fresh_temporary_folder("paper_checks_file");
  rouleau::write_paper_checks(folder.string(), rows);
  std::ifstream file(folder / rouleau::paper_checks_name);
  std::stringstream text;
  text << file.rdbuf();
  EXPECT_EQ(text.str(), csv);
  EXPECT_FALSE(std::filesystem::exists(folder / "paper_checks.csv.tmp"));
}

}  // namespace
