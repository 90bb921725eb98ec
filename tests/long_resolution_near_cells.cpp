// Long tier (ctest -L long; scripts/long_tier.sh): bodies a few fluid elements thick
// against references that do not depend on the code (docs/validation.md, "Resolution near
// the cells"). Each runs a case of cases/ through the rouleau executable and holds its
// diagnostics against the reference with src/analysis.
// - Jeffery (1922): a stiff oblate spheroid (c/a = 1/3) in shear, cases/spheroid_shear,
//   at h_f = 1 and 0.5 μm. Not met at either (period −24 % and −14 %, measured); the
//   test holds the error's fall with h_f (first order: a ratio near 0.5; threshold 0.75)
//   and the step's accuracy at the case's strain per step (the flip within 3 % of the run
//   at half the step). 629 s on 2 cores.
// - Bungay & Brenner (1973): a stiff sphere of a/R = 0.8 and 0.9 on the axis of Poiseuille
//   flow, cases/sphere_in_tube (fluid elements 1 μm, 0.5 μm at the wall), moves at their
//   U/V_mean within 10 % (the threshold of the validation's statement). 247 s.
// - Reversibility: two stiff spheres (a = 2 μm) passing each other in shear,
//   cases/sphere_pair_shear at a/h_f = 1.33, 2 and 2.67: they pass, and the change of
//   their offset across the streamlines falls at each refinement. 424 s.
// - Gaps that open: the four-cell stack started in contact (rims 0.085 μm apart) at
//   3.0 1/s without the interaction, to a strain of 3 at the case's resolution: every
//   neighbour gap grows by more than r0 = 0.25 μm with the sub-grid film model (open gap
//   1.5 μm), and by less than 0.01 μm without it (the fluid alone locks the films).
//   Measured: 2.55-2.75 μm with, 1e-4 μm without; the two runs 40 and 54 s. Deforming films
//   (with the semi-implicit coupling) part it too, hold it with an adhesion whose
//   repulsion can balance its pull, and let the flow part it at a high enough shear rate.
// - Gaps of one to two fluid elements: the paper's stack (rims 1.39 μm apart) at 0.25 1/s
//   without the interaction, to the paper's 4 s (Fig. 8: "the cells keep their vertical
//   separations", every change below 0.5 μm, the threshold set before any run). With the
//   case's elements (1 μm) the stack turns as one body (0.81 μm, not met); with the
//   elements across the gaps (along y, the velocity gradient) halved, met (0.29 μm), and
//   closer to the fully refined run's 0.28 μm. 324 s for the two runs on 2 cores.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/jeffery_orbit.hpp"
#include "analysis/pair_reversibility.hpp"
#include "analysis/sphere_in_tube.hpp"
#include "analysis/scene_checks.hpp"
#include "io/diagnostics_reader.hpp"
#include "run_rouleau.hpp"

namespace {

// Runs cases/NAME/case.toml with `settings` (" --set KEY=VALUE" ...) into a fresh folder;
// returns its diagnostics.
rouleau::DiagnosticsRows run_case(const std::string& name, const std::string& tag, const std::string& settings) {
  const std::string out = fresh_output_dir(name + "_" + tag);
  const Outcome outcome = run_rouleau("run " + std::string(ROULEAU_SOURCE_DIR) + "/cases/" + name + "/case.toml --out " +
                                      out + " --no-progress --set output.fields=false" + settings);
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  return rouleau::read_diagnostics(out + "/diagnostics.csv");
}

// The spheroid case's run against Jeffery's orbit (c/a = 1/3, γ̇ = 10 1/s, the case's).
rouleau::JefferyComparison spheroid_against_jeffery(const std::string& tag, const std::string& settings) {
  const rouleau::DiagnosticsRows rows = run_case("spheroid_shear", tag, settings);
  const double axis_ratio = 0.3333333333, shear_rate = 10.0;
  const rouleau::JefferyComparison c = rouleau::compare_with_jeffery(
      rouleau::diagnostics_column(rows, "time_s"),
      rouleau::symmetry_axis_angles(rouleau::diagnostics_column(rows, "cell0_inclination_deg"), axis_ratio), axis_ratio,
      shear_rate);
  std::printf("Jeffery %s: period %+.2f %%, flip %.4f s (Jeffery %.4f s), RMS %.2f deg: %s\n", tag.c_str(),
              100.0 * c.period_error, c.flip_time, c.jeffery_flip_time, c.rms_angle_error_deg,
              c.met() ? "met" : "not met");
  return c;
}

TEST(ResolutionLong, SpheroidPeriodErrorFallsWithTheFluidMeshAndTheStepIsAccurate) {
  const rouleau::JefferyComparison coarse = spheroid_against_jeffery("h1", "");
  const rouleau::JefferyComparison fine = spheroid_against_jeffery("h05", " --set \"domain.elements=[48,48,48]\"");
  const rouleau::JefferyComparison half_step = spheroid_against_jeffery("h1_half_step", " --set time.dt_s=1.25e-3");
  ASSERT_GT(coarse.measured_period, 0.0);
  ASSERT_GT(fine.measured_period, 0.0);
  std::printf("Jeffery: period error ratio h_f 0.5 / 1 = %.3f\n", fine.period_error / coarse.period_error);
  EXPECT_LT(std::fabs(fine.period_error), 0.75 * std::fabs(coarse.period_error));
  EXPECT_LT(fine.rms_angle_error_deg, coarse.rms_angle_error_deg);
  ASSERT_GT(coarse.flip_time, 0.0);
  ASSERT_GT(half_step.flip_time, 0.0);
  EXPECT_NEAR(coarse.flip_time / half_step.flip_time, 1.0, 0.03);
}

TEST(ResolutionLong, SphereOnATubesAxisMovesAtBungayAndBrennersSpeed) {
  for (const double radius_ratio : {0.8, 0.9}) {
    const double diameter = 2.0 * radius_ratio * 5.0;  // the case's tube: R = 5 μm, V_mean = 10 μm/s
    const std::string tag = radius_ratio == 0.8 ? "08" : "09";
    const rouleau::DiagnosticsRows rows =
        run_case("sphere_in_tube", tag, " --set cell_kinds.plug.diameter_um=" + std::to_string(diameter));
    const rouleau::PlugSpeed plug = rouleau::measure_plug_speed(rows, 0.1);  // the second half of 0.2 s
    const double ratio = plug.speed / 10.0, reference = rouleau::sphere_in_tube_speed_ratio(radius_ratio);
    std::printf("plug a/R = %.1f: U/V_mean = %.4f, Bungay & Brenner %.4f (%+.2f %%), speed spread %.3g um/s\n",
                radius_ratio, ratio, reference, 100.0 * (ratio / reference - 1.0), plug.speed_spread);
    EXPECT_NEAR(ratio / reference, 1.0, 0.1) << "a/R " << radius_ratio;
  }
}

TEST(ResolutionLong, PassingSpheresKeepTheirOffsetBetterOnFinerMeshes) {
  const double radius = 2.0;
  std::vector<rouleau::PairReversibility> runs;
  for (const std::string elements : {"[32,16,11]", "[48,24,16]", "[64,32,22]"}) {
    const rouleau::DiagnosticsRows rows =
        run_case("sphere_pair_shear", elements.substr(1, 2), " --set \"domain.elements=" + elements + "\"");
    runs.push_back(rouleau::measure_pair_reversibility(rows, radius));
    const auto& r = runs.back();
    std::printf("pair %s: offset %.4f -> %.4f um, asymmetry %+.4f, smallest gap %.4f um, %s\n", elements.c_str(),
                r.initial_offset, r.final_offset, r.asymmetry, r.smallest_gap, r.passed ? "passed" : "NOT passed");
    EXPECT_TRUE(r.passed) << elements;
  }
  for (std::size_t i = 1; i < runs.size(); ++i) EXPECT_LT(std::fabs(runs[i].asymmetry), std::fabs(runs[i - 1].asymmetry));
}

TEST(ResolutionLong, StackInContactComesApartInShearWithTheFilmModel) {
  const std::string contact =
      " --set interaction.enabled=false --set time.end_s=1.0"
      " --set boundary.y_min.velocity_um_s=[-30,0,0] --set boundary.y_max.velocity_um_s=[30,0,0]"
      " --set 'cells=[{kind=\"normal\", center_um=[0,-3.975,0], orientation_deg=[90,0,0]},"
      " {kind=\"normal\", center_um=[0,-1.325,0], orientation_deg=[90,0,0]},"
      " {kind=\"normal\", center_um=[0,1.325,0], orientation_deg=[90,0,0]},"
      " {kind=\"normal\", center_um=[0,3.975,0], orientation_deg=[90,0,0]}]'";
  const rouleau::DiagnosticsRows locked = run_case("stack_shear", "contact", contact);
  const rouleau::DiagnosticsRows films =
      run_case("stack_shear", "contact_films", contact + " --set coupling.film_open_gap_um=1.5");
  const double r0 = 0.25;
  const rouleau::StackMeasures before = rouleau::measure_stack(locked, 4, 4, r0);
  for (int c = 0; c < 3; ++c) {
    const std::string gap = "gap_" + std::to_string(c) + "_" + std::to_string(c + 1) + "_um";
    const double with = films.back().at(gap) - films.front().at(gap);
    std::printf("pair of cells in contact %s: grows %.4f um with the film model (strain 3)\n", gap.c_str(), with);
    EXPECT_GT(with, r0) << gap;
  }
  std::printf("pair of cells in contact without the film model: largest growth %.4f um\n", before.largest_gap_growth);
  EXPECT_LT(std::fabs(before.largest_gap_growth), 0.01);
}

TEST(ResolutionLong, DeformingFilmsPartAStackInContactUnlessTheAdhesionHoldsIt) {
  // The stack in contact with deforming films (docs/validation.md, "Gaps that open"), each
  // run at the case's step (2e-3 s) or at 0.006 of strain per step, the smaller (0.024 at
  // 300 1/s, within the coupling's accurate range: docs/validation.md, "Rotation"). A film
  // "parts" when every neighbour gap grows by more than r0 = 0.25 μm; it "holds" when no gap
  // grows by that much and none drains below 0.01 μm. Without the interaction, at 3 1/s to a strain of 3: parts. With the calibrated
  // law (β = 4/μm) at 0.25 1/s, 0.2 s: drains, every gap below 0.01 μm. With β = 8/μm and
  // the depth for the same 1 μJ/m² (De = 1.8145 pN/μm³), whose repulsion between flat faces
  // peaks at 8.4 Pa against 3.1 Pa of attraction: holds at 0.25 1/s (0.2 s) and at 30 1/s
  // (strain 3), and parts at 300 1/s (strain 2.4; measured 0.9-1.8 μm of growth there; the run
  // to strain 3 stopped at 2.76, step 117, its Newton solve 8e-10 short of 1e-10).
  const std::string contact =
      " --set coupling.film_open_gap_um=1.5 --set coupling.film_model=\"deforming\""
      " --set 'cells=[{kind=\"normal\", center_um=[0,-3.975,0], orientation_deg=[90,0,0]},"
      " {kind=\"normal\", center_um=[0,-1.325,0], orientation_deg=[90,0,0]},"
      " {kind=\"normal\", center_um=[0,1.325,0], orientation_deg=[90,0,0]},"
      " {kind=\"normal\", center_um=[0,3.975,0], orientation_deg=[90,0,0]}]'";
  const auto sheared = [](double rate, double strain, double strain_per_step = 0.006) {
    const std::string wall = std::to_string(10.0 * rate);
    return " --set boundary.y_min.velocity_um_s=[-" + wall + ",0,0] --set boundary.y_max.velocity_um_s=[" + wall +
           ",0,0] --set time.dt_s=" + std::to_string(std::fmin(2e-3, strain_per_step / rate)) +
           " --set time.end_s=" + std::to_string(strain / rate);
  };
  const std::string stiff = " --set interaction.beta_per_um=8 --set interaction.well_depth_pN_um3=1.8145";
  const double r0 = 0.25;
  struct Run {
    const char* tag;
    std::string settings;
    const char* expected;  // "parts", "holds" or "drains"
  };
  const std::vector<Run> runs = {
      {"contact_deforming", contact + " --set interaction.enabled=false" + sheared(3.0, 3.0), "parts"},
      {"contact_adhesive", contact + sheared(0.25, 0.05), "drains"},
      {"contact_adhesive_stiff_0.25", contact + stiff + sheared(0.25, 0.05), "holds"},
      {"contact_adhesive_stiff_30", contact + stiff + sheared(30.0, 3.0), "holds"},
      {"contact_adhesive_stiff_300", contact + stiff + sheared(300.0, 2.4, 0.024), "parts"},
  };
  for (const Run& run : runs) {
    const rouleau::DiagnosticsRows rows = run_case("stack_shear", run.tag, run.settings);
    ASSERT_FALSE(rows.empty()) << run.tag;
    double least_growth = INFINITY, most_growth = -INFINITY, least_gap = INFINITY, last_largest = 0.0;
    for (int c = 0; c < 3; ++c) {
      const std::string gap = "gap_" + std::to_string(c) + "_" + std::to_string(c + 1) + "_um";
      const double growth = rows.back().at(gap) - rows.front().at(gap);
      least_growth = std::fmin(least_growth, growth);
      most_growth = std::fmax(most_growth, growth);
      last_largest = std::fmax(last_largest, rows.back().at(gap));
      for (const auto& row : rows) least_gap = std::fmin(least_gap, row.at(gap));
    }
    std::printf("stack in contact, deforming films, %s: gaps grow %.4f to %.4f um, least %.5f um, largest at the end "
                "%.5f um (expected: %s)\n",
                run.tag, least_growth, most_growth, least_gap, last_largest, run.expected);
    const std::string expected = run.expected;
    if (expected == "parts") {
      EXPECT_GT(least_growth, r0) << run.tag;
    } else if (expected == "drains") {
      EXPECT_LT(last_largest, 0.01) << run.tag;
    } else {
      EXPECT_LT(most_growth, r0) << run.tag;
      EXPECT_GT(least_gap, 0.01) << run.tag;
    }
  }
}

TEST(ResolutionLong, PaperStackKeepsItsSeparationsWhenTheFluidResolvesItsGaps) {
  const std::string fig8 =
      " --set interaction.enabled=false --set time.end_s=4"
      " --set boundary.y_min.velocity_um_s=[-2.5,0,0] --set boundary.y_max.velocity_um_s=[2.5,0,0]";
  const double r0 = 0.25, shear_rate = 0.25;
  struct Run {
    const char* tag;
    const char* elements;
    bool expected_met;
  };
  for (const Run& run : {Run{"fig8_case_mesh", "[24,20,16]", false}, Run{"fig8_gaps_resolved", "[24,40,16]", true}}) {
    const rouleau::DiagnosticsRows rows =
        run_case("stack_shear", run.tag, fig8 + " --set \"domain.elements=" + std::string(run.elements) + "\"");
    ASSERT_FALSE(rows.empty()) << run.tag;
    const rouleau::StackMeasures m = rouleau::measure_stack(rows, 4, 4, r0);
    const rouleau::StackStatement s = rouleau::check_stack_statement(m, shear_rate, false, r0);
    std::printf("paper stack without the interaction, elements %s: largest separation change %.4f um, mean "
                "inclination %.2f deg, stack axis %.2f deg: %s\n",
                run.elements, m.largest_separation_change, m.mean_inclination_deg, m.stack_axis_deg,
                s.met ? "met" : "not met");
    EXPECT_EQ(s.figure, "Fig. 8");
    EXPECT_EQ(s.met, run.expected_met) << run.tag << ": " << s.measured;
  }
}

}  // namespace
