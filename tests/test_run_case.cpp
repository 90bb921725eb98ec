// Regression tests of whole runs through the real executable: the shear_flow and channel
// cases at reduced size, checked against exact values, and the divergence path (exit code
// 3 and the last good checkpoint). Checkpoints, restart and signals: test_restart.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <vector>

#include "io/checkpoint_file.hpp"
#include "io/diagnostics_reader.hpp"
#include "io/run_folder.hpp"
#include "mesh/fluid_mesh.hpp"
#include "hdf5_reading.hpp"
#include "run_rouleau.hpp"

namespace {

const std::string cases_dir = std::string(ROULEAU_SOURCE_DIR) + "/cases";

// The discrete mean of the parabola 6s(1 − s) interpolated linearly between the nodes of
// `elements` intervals graded by `grading` on [0, 1] (the trapezoid rule).
double nodal_parabola_mean(int elements, double grading) {
  const auto y = rouleau::graded_coordinates(0.0, 1.0, elements, grading);
  double mean = 0.0;
  for (size_t i = 0; i + 1 < y.size(); ++i) mean += (y[i + 1] - y[i]) * 3.0 * (y[i] * (1 - y[i]) + y[i + 1] * (1 - y[i + 1]));
  return mean;
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
  for (const char* file : {"fields.xdmf", "fields_mesh.h5", "fields_000004.h5", "case.resolved.toml", "run.log"})
    EXPECT_TRUE(std::filesystem::exists(out + "/" + file)) << file;
  // The diagnostics start with the state at t = 0.
  const auto rows = rouleau::read_diagnostics(out + "/diagnostics.csv");
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows.front().at("step"), 0.0);
  EXPECT_EQ(rows.front().at("time_s"), 0.0);
  // The run's log holds what it printed: its id first, the stage table with the stages
  // that ran (a fluid alone: no cell stage), the time outside them and the total.
  const std::string log = file_contents(out + "/run.log");
  EXPECT_EQ(log.rfind("rouleau run id ", 0), 0u) << log;
  EXPECT_NE(log.find("fluid mesh: "), std::string::npos) << log;
  const std::size_t table = log.find("time per stage:");
  ASSERT_NE(table, std::string::npos) << log;
  for (const char* line : {"  fluid", "  outside the stages", "  total"})
    EXPECT_NE(log.find(line, table), std::string::npos) << line << " not in\n" << log;
  for (const char* stage : {"elastic", "spread", "interaction", "cell meshes", "cell diagnostics"})
    EXPECT_EQ(log.find(stage, table), std::string::npos) << stage << " in\n" << log;
  // After its first line, the log is what the run printed on stderr.
  EXPECT_EQ(log.substr(log.find('\n') + 1), o.err);
}

// The first line of a run's log names its run id.
std::string run_id_of(const std::string& out) {
  const std::string log = file_contents(out + "/run.log");
  const std::string prefix = "rouleau run id ";
  return log.rfind(prefix, 0) == 0 ? log.substr(prefix.size(), 16) : "";
}

TEST(RunFolder, ASecondRunIntoTheFolderIsRefusedUnlessOverwritten) {
  // A reused output folder once mixed two runs' diagnostics, fields and checkpoints, and a
  // restart continued the older case. Now the second run stops before any work, exit 2.
  const std::string out = fresh_output_dir("reused");
  const std::string small = " --no-progress --set domain.elements=[4,4,2] --set time.end_s=0.1";
  const std::string first = "run " + cases_dir + "/shear_flow/case.toml --out " + out + small;
  ASSERT_EQ(run_rouleau(first).exit_code, 0);
  const std::string first_id = run_id_of(out);
  EXPECT_EQ(first_id.size(), 16u);
  const std::string diagnostics = file_contents(out + "/diagnostics.csv");

  const std::string second = "run " + cases_dir + "/channel/case.toml --out " + out + " --no-progress --set time.end_s=0.1";
  const Outcome refused = run_rouleau(second);
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find(out + ": --out: the folder holds an earlier run (run id " + first_id + ")"),
            std::string::npos)
      << refused.err;
  EXPECT_NE(refused.err.find("--overwrite"), std::string::npos) << refused.err;
  EXPECT_EQ(file_contents(out + "/diagnostics.csv"), diagnostics);
  EXPECT_EQ(run_id_of(out), first_id);

  // --overwrite empties it first: one run, the channel's, with a new id in every file.
  const Outcome overwritten = run_rouleau(second + " --overwrite");
  ASSERT_EQ(overwritten.exit_code, 0) << overwritten.err;
  const std::string second_id = run_id_of(out);
  EXPECT_NE(second_id, first_id);
  EXPECT_EQ(rouleau::single_run_id(out), second_id);
  EXPECT_NE(file_contents(out + "/case.resolved.toml").find("channel"), std::string::npos);

  // --out naming a file: bad input, not an internal error.
  const Outcome on_a_file = run_rouleau("run " + cases_dir + "/shear_flow/case.toml --out " + out + "/run.log" + small);
  EXPECT_EQ(on_a_file.exit_code, 2) << on_a_file.err;
  EXPECT_NE(on_a_file.err.find("names a file, not a folder"), std::string::npos) << on_a_file.err;

  // A checkpoint of the first run put among the second's: the restart refuses the folder.
  const std::string other = fresh_output_dir("reused_other");
  ASSERT_EQ(run_rouleau("run " + cases_dir + "/shear_flow/case.toml --out " + other + small).exit_code, 0);
  std::filesystem::create_directories(out + "/checkpoints");  // the channel's steady run wrote none
  std::filesystem::copy_file(rouleau::newest_valid_checkpoint(other).path, out + "/checkpoints/checkpoint_000000099.h5");
  const Outcome mixed = run_rouleau("run --restart " + out + " --no-progress");
  EXPECT_EQ(mixed.exit_code, 2) << mixed.err;
  EXPECT_NE(mixed.err.find("different runs"), std::string::npos) << mixed.err;
}

TEST(RunCase, CellsAreWrittenInPlaceBesideTheFluid) {
  // The cell gallery at the coarse preset (a steady solve, the cells in place): the output holds a second mesh,
  // "cells", with every cell's nodes, moving coordinates, the nodal fields and the cell
  // ids; each cell's node cloud sits around its placement's centre, within its size.
  const std::string out = fresh_output_dir("cells");
  const std::string cache = out + "_mesh_cache";
  ::setenv("ROULEAU_MESH_CACHE", cache.c_str(), 1);
  std::string coarse;
  for (const char* kind : {"normal", "normal_filled", "sickle", "capsule"})
    coarse += std::string(" --set cell_kinds.") + kind + ".resolution=coarse";
  const Outcome o = run_rouleau("run " + cases_dir + "/cell_gallery/case.toml --no-progress --out " + out + coarse +
                                " --set interaction.enabled=true");
  ::unsetenv("ROULEAU_MESH_CACHE");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const std::string xdmf = file_contents(out + "/fields.xdmf");
  EXPECT_NE(xdmf.find("Name=\"cells\""), std::string::npos);
  // A steady run writes one frame per mesh, the solution: two frames at the same time
  // (t = 0) make ParaView's XDMF reader show nothing at all.
  std::size_t frames = 0;
  for (std::size_t at = xdmf.find("<Time "); at != std::string::npos; at = xdmf.find("<Time ", at + 1)) ++frames;
  EXPECT_EQ(frames, 2u) << "fluid and cells, one frame each";
  EXPECT_NE(xdmf.find("internal_force_pN"), std::string::npos);
  EXPECT_NE(xdmf.find("interaction_force_pN"), std::string::npos);
  // The gallery's cells are more than the 3 μm cut-off apart: no interaction force at all.
  const Dataset interaction = read_dataset(out + "/fields_000001.h5", "/cells/interaction_force_pN", false);
  ASSERT_FALSE(interaction.doubles.empty());
  for (const double f : interaction.doubles) ASSERT_EQ(f, 0.0);
  // The cells' diagnostics: at rest, no elastic energy and no volume change; the list was
  // built once.
  const auto last = rouleau::read_last_diagnostics(out + "/diagnostics.csv");
  EXPECT_NEAR(last.at("elastic_energy_pN_um"), 0.0, 1e-9);
  EXPECT_EQ(last.at("interaction_energy_pN_um"), 0.0);
  EXPECT_EQ(last.at("neighbor_list_rebuilds"), 1.0);
  EXPECT_NEAR(last.at("largest_relative_volume_change"), 0.0, 1e-14);
  EXPECT_NEAR(last.at("smallest_volume_ratio"), 1.0, 1e-12);  // no element compressed
  const Dataset ids = read_dataset(out + "/fields_000001.h5", "/cells/cell_id", false);
  const Dataset x = read_dataset(out + "/fields_000001.h5", "/cells/coordinates", false);
  const Dataset tets = read_dataset(out + "/fields_mesh.h5", "/cells/connectivity", true);
  ASSERT_EQ(x.doubles.size(), 3 * ids.doubles.size());
  ASSERT_EQ(tets.dimensions.size(), 2u);
  EXPECT_EQ(tets.dimensions[1], 4u);
  const double centers[4][3] = {{-21, 0, 0}, {-8, 0, 0}, {7, -1, 0}, {22, 0, 0}};
  double lower[4][3], upper[4][3];
  for (auto& bound : lower) std::fill(bound, bound + 3, 1e300);
  for (auto& bound : upper) std::fill(bound, bound + 3, -1e300);
  std::set<int> seen;
  for (std::size_t n = 0; n < ids.doubles.size(); ++n) {
    const int cell = static_cast<int>(ids.doubles[n]);
    ASSERT_TRUE(cell >= 0 && cell < 4) << cell;
    seen.insert(cell);
    for (int i = 0; i < 3; ++i) {
      lower[cell][i] = std::min(lower[cell][i], x.doubles[3 * n + i]);
      upper[cell][i] = std::max(upper[cell][i], x.doubles[3 * n + i]);
    }
  }
  EXPECT_EQ(seen.size(), 4u);
  // Each body's bounding box contains its centre and is no larger than 15 μm (the sickle).
  for (int c = 0; c < 4; ++c)
    for (int i = 0; i < 3; ++i) {
      EXPECT_LT(lower[c][i], centers[c][i]) << "cell " << c << " axis " << i;
      EXPECT_GT(upper[c][i], centers[c][i]) << "cell " << c << " axis " << i;
      EXPECT_LT(upper[c][i] - lower[c][i], 15.0) << "cell " << c << " axis " << i;
    }
  // The normal cell lies flat (axis z, thin along z), the filled one on its edge (thin along y).
  std::printf("normal cell extent %.3f x %.3f x %.3f um; turned filled cell %.3f x %.3f x %.3f um\n",
              upper[0][0] - lower[0][0], upper[0][1] - lower[0][1], upper[0][2] - lower[0][2],
              upper[1][0] - lower[1][0], upper[1][1] - lower[1][1], upper[1][2] - lower[1][2]);
  EXPECT_NEAR(upper[0][2] - lower[0][2], 2.57, 0.1);
  EXPECT_NEAR(upper[0][0] - lower[0][0], 7.82, 0.1);
  EXPECT_NEAR(upper[1][1] - lower[1][1], 2.57, 0.1);
  EXPECT_NEAR(upper[1][2] - lower[1][2], 7.82, 0.1);
  std::filesystem::remove_all(cache);
}

TEST(RunCase, ChannelFlowRateMatchesHagenPoiseuille) {
  // Pressure-driven plane channel, 0.06 Pa over 40 μm, H = 10 μm: U = Δp H²/(12 μ L) = 10.4167 μm/s.
  // With parallel-flow ends the exact solution is the Poiseuille profile; the mean velocity
  // then carries only the discretization error (12 graded elements across). With pure
  // traction ends (zero tangential traction) the profile adjusts near the ends and the
  // flow rate is measurably higher.
  const double predicted = 0.06 * 100.0 / (12.0 * 1.2e-3 * 40.0);
  double computed[2];
  for (int parallel = 0; parallel < 2; ++parallel) {
    const std::string out = fresh_output_dir("channel" + std::to_string(parallel));
    const std::string setting = parallel ? "true" : "false";
    const Outcome o = run_rouleau("run " + cases_dir + "/channel/case.toml --no-progress --out " + out +
                                  " --set boundary.x_min.parallel_flow=" + setting +
                                  " --set boundary.x_max.parallel_flow=" + setting);
    ASSERT_EQ(o.exit_code, 0) << o.err;
    computed[parallel] = rouleau::read_last_diagnostics(out + "/diagnostics.csv").at("mean_velocity_x_um_s");
    std::printf("channel (parallel_flow = %s): mean velocity %.5f um/s, Hagen-Poiseuille %.5f um/s (%+.2f%%)\n",
                setting.c_str(), computed[parallel], predicted, 100.0 * (computed[parallel] - predicted) / predicted);
  }
  // Linear elements reproduce the parabola at the nodes (1D superconvergence), so the mean
  // of the discrete field is the trapezoid rule of the exact profile 6s(1 − s) over the
  // case's graded nodes: that is what the solver must give, to solver tolerance.
  const double trapezoid = nodal_parabola_mean(12, 1.5);
  std::printf("nodally exact discrete mean: %.5f um/s\n", predicted * trapezoid);
  EXPECT_NEAR(computed[1], predicted * trapezoid, 1e-5 * predicted);
  EXPECT_NEAR(computed[1], predicted, 1e-2 * predicted);
  EXPECT_GT(computed[0] - predicted, 0.01 * predicted);
}

TEST(RunCase, ParabolicInflowIsCarriedThroughTheChannel) {
  // A parabolic inflow of mean 10 μm/s at x = 0 and a parallel-flow outlet: the exact
  // solution is the same Poiseuille profile everywhere, so the volume-averaged velocity
  // must equal the inflow's discrete mean. The small deficit is the stabilization's mass
  // defect next to the Dirichlet inflow; it must fall faster than O(h) under refinement.
  double defect[2];
  const int ny[2] = {12, 24};
  for (int k = 0; k < 2; ++k) {
    const std::string out = fresh_output_dir("inflow" + std::to_string(k));
    const Outcome o = run_rouleau(
        "run " + cases_dir + "/channel/case.toml --no-progress --out " + out + " --set domain.elements=[" +
        std::to_string(2 * ny[k]) + "," + std::to_string(ny[k]) +
        ",3] --set 'boundary.x_min={type=\"inflow\", mean_speed_um_s=10.0, profile=\"parabolic\"}'");
    ASSERT_EQ(o.exit_code, 0) << o.err;
    const double expected = 10.0 * nodal_parabola_mean(ny[k], 1.5);
    const double computed = rouleau::read_last_diagnostics(out + "/diagnostics.csv").at("mean_velocity_x_um_s");
    defect[k] = std::fabs(computed - expected) / expected;
    std::printf("inflow, %d elements across: mean velocity %.5f um/s, inflow's discrete mean %.5f (defect %.3f%%)\n",
                ny[k], computed, expected, 100 * defect[k]);
  }
  EXPECT_LT(defect[0], 5e-3);
  EXPECT_GT(defect[0] / defect[1], 3.0);
}

TEST(RunCase, ContractionWritesTetrahedraAndTheDrivingPressure) {
  // The contraction case's plasma alone, steady, coarsened: the fields are on the vessel's tetrahedra; the
  // outflow equals the inflow (global mass balance, to solver tolerance); the driving
  // pressure is Hagen–Poiseuille's summed over cross-sections plus the entrance and exit
  // losses (the case's own mesh: +3.9 %), so the relative apparent viscosity of plasma lies
  // just above 1.
  const std::string out = fresh_output_dir("contraction");
  const Outcome o = run_rouleau("run " + cases_dir + "/contraction/case.toml --no-progress --out " + out +
                                " --set 'cells=[]' --set interaction.enabled=false --set 'time.mode=\"steady\"'"
                                " --set solver.gmres_rtol=1e-8"
                                " --set vessel.element_size_um=3.0 --set vessel.wall_element_size_um=1.5");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto row = rouleau::read_last_diagnostics(out + "/diagnostics.csv");
  const double inflow = row.at("flow_rate_inlet_um3_s"), outflow = row.at("flow_rate_outlet_um3_s");
  std::printf("contraction (coarse): inflow %.3f, outflow %.3f um^3/s; driving pressure %.4f Pa, relative apparent "
              "viscosity %.4f, mean wall shear stress %.4f Pa\n",
              inflow, outflow, row.at("driving_pressure_Pa"), row.at("relative_apparent_viscosity"),
              row.at("mean_wall_shear_stress_Pa"));
  EXPECT_NEAR(outflow, inflow, 1e-5 * inflow);
  // π R² U with R = 6 μm, U = 10 μm/s, less the polygonal inlet's O(h²) deficit.
  EXPECT_NEAR(inflow, 3.14159265358979 * 36.0 * 10.0, 0.06 * 3.14159265358979 * 36.0 * 10.0);
  EXPECT_GT(row.at("relative_apparent_viscosity"), 1.0);
  EXPECT_LT(row.at("relative_apparent_viscosity"), 1.1);
  EXPECT_GT(row.at("mean_wall_shear_stress_Pa"), 0.0);
  EXPECT_NE(file_contents(out + "/fields.xdmf").find("TopologyType=\"Tetrahedron\""), std::string::npos);
  // The figures of a vessel run (matplotlib from Debian, installed by scripts/bootstrap.sh).
  const std::string figures = out + "/figures";
  // Run as the README says, by the script's own first line (Debian's interpreter, which has
  // python3-matplotlib), with another python3 first on PATH as on many machines: a
  // `#!/usr/bin/env python3` script would find that one, without matplotlib.
  const std::string decoy = fresh_output_dir("contraction_decoy_python");
  ASSERT_EQ(std::system(("mkdir -p " + decoy + " && printf '#!/bin/sh\\nexit 97\\n' > " + decoy +
                         "/python3 && chmod +x " + decoy + "/python3").c_str()),
            0);
  ASSERT_EQ(std::system(("PATH=" + decoy + ":$PATH " + std::string(ROULEAU_SOURCE_DIR) + "/scripts/plot_diagnostics.py " +
                         out + " > /dev/null").c_str()),
            0);
  for (const char* name : {"driving_pressure.png", "wall_stress.png", "solver.png"}) {
    const std::string png = file_contents(figures + "/" + name);
    EXPECT_GT(png.size(), 1000u) << name;
    EXPECT_EQ(png.substr(1, 3), "PNG") << name;
  }
}

TEST(RunCase, CellsEnterTheContractionNormalAndSickle) {
  // cases/contraction/case.toml coarsened, three semi-implicit steps of 1e-3 s (twice the case's):
  // the three normal cells, and the sickle variant (ten times stiffer, five times
  // stickier, whose explicit step would be 1.7e-5 s), run, move downstream and keep their
  // volumes.
  const std::string coarse = " --set vessel.element_size_um=3.0 --set vessel.wall_element_size_um=1.5"
                             " --set time.dt_s=1e-3 --set time.end_s=0.003 --set output.fields=false"
                             " --set output.diagnostics_every_steps=1";
  for (const std::string variant : {std::string(), std::string(" --set 'cells=[{kind=\"sickle\", center_um=[9, 0, 0]}]'")}) {
    const std::string out = fresh_output_dir(variant.empty() ? "contraction_normal" : "contraction_sickle");
    const Outcome o = run_rouleau("run " + cases_dir + "/contraction/case.toml --no-progress --out " + out + coarse +
                                  variant);
    ASSERT_EQ(o.exit_code, 0) << o.err;
    const auto rows = rouleau::read_diagnostics(out + "/diagnostics.csv");
    ASSERT_EQ(rows.size(), 4u);  // t = 0 and 3 steps
    const double start = variant.empty() ? 5.0 : 9.0;  // cell 0's centre in the case
    std::printf("contraction (coarse) %s: cell 0 at x = %.4f um after 3 ms, largest volume change %.2e\n",
                variant.empty() ? "normal cells" : "sickle cell", rows.back().at("cell0_centroid_x_um"),
                rows.back().at("largest_relative_volume_change"));
    EXPECT_GT(rows.back().at("cell0_centroid_x_um"), start + 0.01);
    EXPECT_LT(rows.back().at("largest_relative_volume_change"), 1e-3);
    // Moving, the cells deform a little: the most compressed element below 1, far from 0.
    EXPECT_LT(rows.back().at("smallest_volume_ratio"), 1.0);
    EXPECT_GT(rows.back().at("smallest_volume_ratio"), 0.5);
  }
}

TEST(RunCase, CapsuleEntersTheCapillaryCase) {
  // The capillary case with its capsule, coarsened, three semi-implicit steps of 1e-3 s (twice the
  // case's): the run completes, the
  // capsule moves downstream, and the driving pressure is in the diagnostics.
  const std::string out = fresh_output_dir("capillary");
  const Outcome o = run_rouleau("run " + cases_dir + "/capillary/case.toml --no-progress --out " + out +
                                " --set vessel.element_size_um=3.0 --set vessel.wall_element_size_um=1.5"
                                " --set time.dt_s=1e-3 --set time.end_s=0.003");
  ASSERT_EQ(o.exit_code, 0) << o.err;
  const auto row = rouleau::read_last_diagnostics(out + "/diagnostics.csv");
  std::printf("capillary (coarse), 3 steps: capsule centroid x %.5f um, driving pressure %.4f Pa\n",
              row.at("cell0_centroid_x_um"), row.at("driving_pressure_Pa"));
  EXPECT_GT(row.at("cell0_centroid_x_um"), 7.0);
  EXPECT_GT(row.at("driving_pressure_Pa"), 0.0);
  EXPECT_LT(row.at("largest_relative_volume_change"), 1e-3);
}

TEST(RunCase, ExplainListsTheStokesLimitAndSkippedStages) {
  const Outcome o = run_rouleau("run " + cases_dir + "/shear_flow/case.toml --explain --out " +
                                fresh_output_dir("explain"));
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.out.find("Stokes limit"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("[skip] Morse"), std::string::npos) << o.out;
  // A uniform box in the Stokes limit: the operator runs as a stencil, unless skips are off.
  EXPECT_NE(o.out.find("fluid operator: stencil from one reference element"), std::string::npos) << o.out;
  const Outcome all = run_rouleau("run " + cases_dir + "/shear_flow/case.toml --explain --out " +
                                  fresh_output_dir("explain_all") + " --set scene.skip_unneeded_stages=false");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_NE(all.out.find("fluid operator: element by element"), std::string::npos) << all.out;
}

// A run that diverged before any periodic checkpoint names step 0's as the last good one.
void expect_step_0_named_as_last_good(const std::string& err, const std::string& out) {
  EXPECT_NE(err.find("last good checkpoint: " + out + "/checkpoints/checkpoint_000000000.h5"), std::string::npos)
      << err;
}

TEST(RunCase, SolverFailureStopsWithStepStageAndExitCode3) {
  // Two GMRES iterations cannot solve the Stokes system with the multigrid (the fast
  // diagonalization, the default on this box, solves it in at most 3): the run must stop at
  // step 1, name the stage and the values, and exit 3 (diverged), not crash or write NaNs.
  const std::string out = fresh_output_dir("diverge");
  const Outcome o = run_rouleau("run " + cases_dir + "/shear_flow/case.toml --no-progress --out " + out +
                                " --set solver.gmres_max_iterations=2 --set solver.gmres_restart=2" +
                                " --set solver.preconditioner=multigrid");
  EXPECT_EQ(o.exit_code, 3) << o.err;
  EXPECT_NE(o.err.find("step 1"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("stage fluid"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("GMRES did not converge"), std::string::npos) << o.err;
  // The checkpoint of step 0 is the last good state, and the message names it.
  expect_step_0_named_as_last_good(o.err, out);
  EXPECT_NO_THROW(rouleau::read_checkpoint_file(out + "/checkpoints/checkpoint_000000000.h5"));
}

TEST(RunCase, VolumeDriftStopsTheRunNamingTheCellAndTheLastCheckpoint) {
  // The reduced two-cell aggregation with ten times its well depth (25 μJ/m²), explicit,
  // the cells moving with u_h (with u_h + u' this step holds), at ten times its stable step
  // (allowed on purpose): the cells' volumes swing by several per cent within a few steps. With a 2 %
  // tolerance the run must stop as diverged (exit 3) at the step that crossed it, naming
  // the stage, the cell, its volume and the last good checkpoint.
  const std::string out = fresh_output_dir("volume");
  const Outcome o = run_rouleau("run " + cases_dir + "/aggregation/case.toml --no-progress --threads 1 --out " + out +
                                " --set domain.elements=[12,12,10] --set cell_kinds.normal.resolution=coarse"
                                " --set output.fields=false --set time.end_s=0.00068 --set time.dt_s=8.5e-5"
                                " --set coupling.allow_unstable_step=true --set coupling.volume_tolerance=0.02"
                                " --set interaction.strength_multiplier=50 --set coupling.subscale_velocity=false");
  EXPECT_EQ(o.exit_code, 3) << o.err;
  EXPECT_NE(o.err.find("stage move cells: cell "), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("enclosed volume is"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("coupling.volume_tolerance = 0.02"), std::string::npos) << o.err;
  expect_step_0_named_as_last_good(o.err, out);
}

}  // namespace
