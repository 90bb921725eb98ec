// `mpirun -np 2 rouleau run` through the real executable: the fluid split
// across two ranks, every cell on both, each computed by the rank holding its centroid
// (the rank owning the fluid node nearest to it). Compared with
// the same case on one rank:
//   - point-block Jacobi GMRES takes the same iterates on any rank count: the runs differ
//     only as the sums meet in another order, which a change of thread count on one rank
//     does too; each solve passes that round-off on at the level of its stopping test, so
//     the solvers run to 1e-9 here (block Jacobi's GMRES creeps near that on this case);
//   - the multigrid and ILU(0) of one rank become additive Schwarz with the multigrid or
//     ILU(0) of each rank's block on two: there the answers agree to the solvers' tolerance;
// and a checkpoint written on two ranks continues on one and back (it holds the global
// state). A cell whose centroid crosses from one rank's part of the fluid into the
// other's changes rank and keeps its volume and forces. A divergence on two ranks stops
// both with exit code 3, naming the checkpoint.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hdf5_reading.hpp"
#include "io/diagnostics_reader.hpp"
#include "mpi_launcher.hpp"
#include "reduced_aggregation.hpp"
#include "run_rouleau.hpp"

namespace {

// `mpiexec … -n RANKS` (tests/CMakeLists.txt), empty in a build without MPI.
std::string on_ranks(int ranks) { return std::string(ROULEAU_MPIEXEC) + " " + std::to_string(ranks); }
bool built_with_mpi() { return !std::string(ROULEAU_MPIEXEC).empty(); }

// Point-block Jacobi, GMRES to 1e-9 of the right-hand side.
const std::string block_jacobi = " --set solver.preconditioner=block_jacobi --set solver.gmres_rtol=1e-9";

// The reduced aggregation (tests/reduced_aggregation.hpp) on a box of 10 x 10 x 12
// elements, which two ranks split at z = 0, between the two cells' centroids (z = ±1.535):
// each rank computes one cell, and the Morse pairs join points of both ranks' cells.
std::string split_aggregation(const std::string& out, int steps) {
  return reduced_aggregation(out, 1, steps) + " --set domain.elements=[10,10,12]";
}

}  // namespace

TEST(MpiRun, TwoRanksRepeatTheOneRankRunToRoundOff) {
  if (!built_with_mpi()) GTEST_SKIP() << "a build without MPI";
  // The reduced two-cell aggregation (semi-implicit coupling, Morse forces), 4 steps, one
  // thread per rank, split between the cells (split_aggregation): the cells' stiffness acts
  // inside every GMRES iteration on the fluid replicated from both ranks, each rank
  // computing one of the two cells. Measured (max |a − b| / max |a| over the checkpoint's
  // entries): 1.6e-9 for two ranks against one (8.2e-10 in the fluid's state), 2.7e-9 for
  // two threads against one on one rank (2.2e-9 in the fluid's state); bound 1e-7, a
  // hundred times the solvers' 1e-9 (as test_restart bounds a change of thread count by
  // ten times its 1e-8).
  const std::string one = fresh_output_dir("mpi_one_rank"), two = fresh_output_dir("mpi_two_ranks");
  const Outcome single = run_rouleau(split_aggregation(one, 4) + block_jacobi);
  ASSERT_EQ(single.exit_code, 0) << single.err;
  const Outcome split = run_rouleau(split_aggregation(two, 4) + block_jacobi, on_ranks(2));
  ASSERT_EQ(split.exit_code, 0) << split.err;
  EXPECT_NE(split.err.find("2 MPI ranks"), std::string::npos) << split.err;
  EXPECT_NE(split.err.find("cells computed by the rank holding their centroid; per rank: 1, 1"), std::string::npos)
      << split.err;
  // One log (the first rank's), one diagnostics file, one field series.
  EXPECT_EQ(split.err.find("fluid mesh:"), split.err.rfind("fluid mesh:")) << split.err;
  EXPECT_TRUE(std::filesystem::exists(two + "/fields.xdmf"));
  EXPECT_TRUE(expect_states_agree(one, two, 4, 1e-7)) << "two ranks sum in another order: some bits must differ";
  const auto rows_one = rouleau::read_diagnostics(one + "/diagnostics.csv");
  const auto rows_two = rouleau::read_diagnostics(two + "/diagnostics.csv");
  ASSERT_EQ(rows_one.size(), 5u);  // t = 0 and 4 steps
  ASSERT_EQ(rows_two.size(), 5u);
  // The GMRES counts are not compared: block Jacobi's GMRES creeps near its floor here,
  // where round-off moves the step that crosses 1e-9 (measured per step: 145, 360, 126, 120
  // on one thread, 144, 370, 127, 120 on two, 144, 285, 127, 121 on two ranks).
  for (std::size_t r = 0; r < rows_one.size(); ++r) {
    EXPECT_NEAR(rows_one[r].at("elastic_energy_pN_um"), rows_two[r].at("elastic_energy_pN_um"),
                1e-7 * std::fabs(rows_one[r].at("elastic_energy_pN_um")));
  }
}

TEST(MpiRun, ACheckpointOfTwoRanksContinuesOnOneAndBack) {
  if (!built_with_mpi()) GTEST_SKIP() << "a build without MPI";
  // 8 steps on one rank, against 3 on two ranks, 3 more on one and the last 2 on two, all
  // with point-block Jacobi to 1e-9: the states agree as in the test above.
  const std::string straight = fresh_output_dir("mpi_straight"), split = fresh_output_dir("mpi_split");
  ASSERT_EQ(run_rouleau(split_aggregation(straight, 8) + block_jacobi).exit_code, 0);
  const Outcome first = run_rouleau(split_aggregation(split, 3) + block_jacobi, on_ranks(2));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const Outcome second =
      run_rouleau("run --restart " + split + " --threads 1 --no-progress" + block_jacobi + end_after(6));
  ASSERT_EQ(second.exit_code, 0) << second.err;
  const Outcome third = run_rouleau("run --restart " + split + " --threads 1 --no-progress" + block_jacobi +
                                        end_after(8),
                                    on_ranks(2));
  ASSERT_EQ(third.exit_code, 0) << third.err;
  expect_states_agree(straight, split, 8, 1e-7);
  EXPECT_EQ(rouleau::read_diagnostics(split + "/diagnostics.csv").size(), 9u);  // t = 0 and 8 steps
}

TEST(MpiRun, VesselOnTwoRanksAgreesWithOneRankToTheSolverTolerance) {
  if (!built_with_mpi()) GTEST_SKIP() << "a build without MPI";
  // The contraction (tetrahedra split by METIS, three cells, semi-implicit coupling), one
  // step of 5e-4 s, with the case's multigrid: on one rank against the multigrid of each
  // rank's block on two (78 and 88 GMRES iterations), GMRES to 1e-9 of the right-hand
  // side: the states must agree to 1e-7 (measured: 1.8e-10 in the fluid's state, 3.8e-10
  // in the cells' velocities).
  const std::string settings = " --threads 1 --no-progress --set solver.gmres_rtol=1e-9 --set time.end_s=5e-4";
  const std::string contraction = cases_dir + "/contraction/case.toml";
  const std::string one = fresh_output_dir("mpi_vessel_one"), two = fresh_output_dir("mpi_vessel_two");
  const Outcome single = run_rouleau("run " + contraction + " --out " + one + settings);
  ASSERT_EQ(single.exit_code, 0) << single.err;
  const Outcome split = run_rouleau("run " + contraction + " --out " + two + settings, on_ranks(2));
  ASSERT_EQ(split.exit_code, 0) << split.err;
  expect_states_agree(one, two, 1, 1e-7);
  // The diagnostics sum the ranks' shares: the cell nodes whose RKPM weights needed the
  // wall correction, counted once (1038 in this contraction at its first step).
  const auto rows_one = rouleau::read_diagnostics(one + "/diagnostics.csv");
  const auto rows_two = rouleau::read_diagnostics(two + "/diagnostics.csv");
  ASSERT_FALSE(rows_one.empty());
  ASSERT_EQ(rows_one.size(), rows_two.size());
  EXPECT_GT(rows_one.back().at("rkpm_corrected_points"), 0.0);
  EXPECT_EQ(rows_one.back().at("rkpm_corrected_points"), rows_two.back().at("rkpm_corrected_points"));
}

TEST(MpiRun, ACellCrossingIntoTheOtherRanksPartKeepsItsVolumeAndForces) {
  if (!built_with_mpi()) GTEST_SKIP() << "a build without MPI";
  // rbc_shear (explicit coupling, 24 x 16 x 16 box, γ̇ = 50 1/s) with the cell's centre at
  // x = 0.45, y = 2 μm, where the flow carries it along +x at about 100 μm/s. Two ranks split
  // the box at x = 0; the first owns that plane of nodes, so it holds points up to x = 0.5,
  // and the cell's centroid crosses into the second rank's part within the 6 steps of
  // 2e-4 s: the cell changes rank once. Against one rank, with point-block Jacobi to 1e-9:
  // the checkpoints' states within 1e-7 (measured 4.4e-13 in the fluid's state, 3.5e-16
  // in the cell's positions), the cell's volume at every step within 1e-9 of itself
  // (measured 3e-16) and the internal forces written at the last step (summed over the
  // ranks' shares) within 1e-7 (measured 8.7e-13).
  std::ifstream case_file(cases_dir + "/rbc_shear/case.toml");
  std::stringstream text;
  text << case_file.rdbuf();
  std::string crossing = text.str();
  const std::string centre = "center_um = [0.0, 0.0, 0.0]";
  const std::size_t at = crossing.find(centre);
  ASSERT_NE(at, std::string::npos) << "cases/rbc_shear/case.toml no longer places the cell at the origin";
  crossing.replace(at, centre.size(), "center_um = [0.45, 2.0, 0.0]");
  const std::string case_path = fresh_output_dir("mpi_crossing_case") + ".toml";
  std::ofstream(case_path) << crossing;

  const std::string settings = " --threads 1 --no-progress --set time.end_s=1.2e-3 "
                               "--set output.diagnostics_every_steps=1" + block_jacobi;
  const std::string one = fresh_output_dir("mpi_crossing_one"), two = fresh_output_dir("mpi_crossing_two");
  const Outcome single = run_rouleau("run " + case_path + " --out " + one + settings);
  ASSERT_EQ(single.exit_code, 0) << single.err;
  const Outcome split = run_rouleau("run " + case_path + " --out " + two + settings, on_ranks(2));
  ASSERT_EQ(split.exit_code, 0) << split.err;
  EXPECT_NE(split.err.find("cells computed by the rank holding their centroid; per rank: 1, 0"), std::string::npos)
      << split.err;
  EXPECT_NE(split.err.find("cells changed rank 1 times in this run; per rank now: 0, 1"), std::string::npos)
      << split.err;

  expect_states_agree(one, two, 6, 1e-7);
  const auto rows_one = rouleau::read_diagnostics(one + "/diagnostics.csv");
  const auto rows_two = rouleau::read_diagnostics(two + "/diagnostics.csv");
  ASSERT_EQ(rows_one.size(), 7u);  // t = 0 and 6 steps
  ASSERT_EQ(rows_two.size(), 7u);
  double volume_gap = 0.0;
  for (std::size_t r = 0; r < rows_one.size(); ++r) {
    const double volume = rows_one[r].at("cell0_volume_um3");
    volume_gap = std::max(volume_gap, std::fabs(rows_two[r].at("cell0_volume_um3") / volume - 1.0));
  }
  const Dataset force_one = read_dataset(one + "/fields_000006.h5", "cells/internal_force_pN", false);
  const Dataset force_two = read_dataset(two + "/fields_000006.h5", "cells/internal_force_pN", false);
  ASSERT_EQ(force_one.doubles.size(), force_two.doubles.size());
  ASSERT_FALSE(force_one.doubles.empty());
  double largest = 0.0, force_gap = 0.0;
  for (std::size_t i = 0; i < force_one.doubles.size(); ++i) {
    largest = std::max(largest, std::fabs(force_one.doubles[i]));
    force_gap = std::max(force_gap, std::fabs(force_one.doubles[i] - force_two.doubles[i]));
  }
  std::printf("crossing cell: volume %.1e, internal forces %.1e (relative to the largest, %.3g pN)\n", volume_gap,
              force_gap / largest, largest);
  EXPECT_LT(volume_gap, 1e-9);
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(force_gap / largest, 1e-7);
}

TEST(MpiRun, ADivergenceOnTwoRanksStopsBothWithExitCode3NamingTheCheckpoint) {
  if (!built_with_mpi()) GTEST_SKIP() << "a build without MPI";
  const std::string out = fresh_output_dir("mpi_diverged");
  const Outcome run =
      run_rouleau(split_aggregation(out, 4) + block_jacobi + " --set solver.gmres_max_iterations=2", on_ranks(2));
  EXPECT_EQ(run.exit_code, 3) << run.err;
  const std::string checkpoint = "last good checkpoint: " + out + "/checkpoints/checkpoint_000000000.h5";
  EXPECT_NE(run.err.find("diverged at step 1"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(checkpoint), std::string::npos) << run.err;
  EXPECT_TRUE(std::filesystem::exists(out + "/checkpoints/checkpoint_000000000.h5"));
}
