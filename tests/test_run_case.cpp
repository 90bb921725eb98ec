// Regression tests of whole runs through the real executable: the shear_flow and channel
// cases at reduced size, checked against exact values, and the divergence path.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "io/diagnostics_reader.hpp"
#include "run_rouleau.hpp"

namespace {

const std::string cases_dir = std::string(ROULEAU_SOURCE_DIR) + "/cases";

std::string fresh_output_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("rouleau_run_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir.string();
}

TEST(RunCase, ShearFlowOfPlasmaHasRelativeViscosityOne) {
  // Simple shear at 0.5 1/s on a reduced mesh: τ_w = μ γ̇ exactly, so the relative apparent
  // viscosity is 1 to solver tolerance, and the mean velocity is 0 by symmetry.
  const std::string out = fresh_output_dir("shear");
  const Outcome o = run_rouleau("run " + cases_dir + "/shear_flow/case.toml --no-progress --out " + out +
                                " --set domain.elements=[4,4,2] --set time.end_s=0.2");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto last = rouleau::read_last_diagnostics(out + "/diagnostics.csv");
  std::printf("relative apparent viscosity %.12f, wall shear stress %.6e Pa (exact 6e-4)\n",
              last.at("relative_apparent_viscosity"), last.at("wall_shear_stress_y_max_Pa"));
  EXPECT_NEAR(last.at("relative_apparent_viscosity"), 1.0, 1e-6);
  EXPECT_NEAR(last.at("wall_shear_stress_y_max_Pa"), 1.2e-3 * 0.5, 1e-9);
  EXPECT_NEAR(last.at("time_s"), 0.2, 1e-12);
  for (const char* file : {"fluid.xdmf", "fluid_mesh.h5", "fluid_000004.h5", "case.resolved.toml"})
    EXPECT_TRUE(std::filesystem::exists(out + "/" + file)) << file;
}

TEST(RunCase, ChannelFlowRateMatchesHagenPoiseuille) {
  // Pressure-driven plane channel, 0.06 Pa over 40 μm, H = 10 μm: U = Δp H²/(12 μ L) = 10.4167 μm/s.
  // The pure traction ends (σ·n = −p n) let the profile adjust near the inlet and outlet,
  // which costs a few percent of the flow rate on this short channel.
  const std::string out = fresh_output_dir("channel");
  const Outcome o = run_rouleau("run " + cases_dir + "/channel/case.toml --no-progress --out " + out);
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const double predicted = 0.06 * 100.0 / (12.0 * 1.2e-3 * 40.0);
  const double computed = rouleau::read_last_diagnostics(out + "/diagnostics.csv").at("mean_velocity_x_um_s");
  std::printf("channel mean velocity %.5f um/s, Hagen-Poiseuille %.5f um/s (%.2f%%)\n", computed, predicted,
              100.0 * (computed - predicted) / predicted);
  EXPECT_NEAR(computed, predicted, 0.03 * predicted);
}

TEST(RunCase, ExplainListsTheStokesLimitAndSkippedStages) {
  const Outcome o = run_rouleau("run " + cases_dir + "/shear_flow/case.toml --explain --out " +
                                fresh_output_dir("explain"));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.out.find("Stokes limit"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("[skip] Morse"), std::string::npos) << o.out;
}

TEST(RunCase, SolverFailureStopsWithStepStageAndExitCode3) {
  // Two GMRES iterations cannot solve the Stokes system: the run must stop at step 1,
  // name the stage and the values, and exit 3 (diverged), not crash or write NaNs.
  const std::string out = fresh_output_dir("diverge");
  const Outcome o = run_rouleau("run " + cases_dir + "/shear_flow/case.toml --no-progress --out " + out +
                                " --set solver.gmres_max_iterations=2 --set solver.gmres_restart=2");
  EXPECT_EQ(o.exit_code, 3) << o.err;
  EXPECT_NE(o.err.find("step 1"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("stage fluid"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("GMRES did not converge"), std::string::npos) << o.err;
}

}  // namespace
