// Each cause of divergence stops the step with the stage and the offending values named
// (docs/running.md, "Divergence"): a NaN in the fluid state, a NaN reaching a cell's
// forces, an inverted cell element, a cell that has left the fluid domain. Each test
// breaks one thing in a running two-capsule scene and checks the DivergenceError's
// message. (GMRES not converging and a cell's volume drift are tested through the
// executable, with the exit code and the last good checkpoint, in test_run_case.cpp.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <Kokkos_Core.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "config/load_case.hpp"
#include "kernels/state_checks.hpp"
#include "run/simulation.hpp"
#include "sphere_in_shear.hpp"
#include "util/errors.hpp"
#include "temporary_folder.hpp"

namespace {

using rouleau::Simulation;
using rouleau::testing::host;
using rouleau::testing::HostVectors;

// Two coarse capsules side by side in a 20 μm shear box at 0.5 1/s, one step taken.
class Divergence : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = rouleau::testing::fresh_temporary_folder(
        "divergence_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    const std::string path = (folder_ / "case.toml").string();
    std::ofstream(path) << rouleau::testing::shear_box(20.0, 8, 5.0)
                        << "[time]\ndt_s = 1e-4\nend_s = 1\n"
                           "[cell_kinds.capsule]\nresolution = \"coarse\"\n"
                           "[[cells]]\nkind = \"capsule\"\ncenter_um = [-4.5, 0, 0]\n"
                           "[[cells]]\nkind = \"capsule\"\ncenter_um = [4.5, 0, 0]\n";
    simulation_ = std::make_unique<Simulation>(rouleau::load_case(path), (folder_ / "meshes").string());
    simulation_->advance();
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  const rouleau::CellPopulation& cells() const { return *simulation_->cells().population; }
  // The first node of cell 1.
  int first_node_of_second_cell() const { return cells().cell_first_node()[1]; }
  void set_positions(const HostVectors& x) { simulation_->set_cell_positions(x); }

  // The message of the DivergenceError that the next step throws ("" when it does not).
  std::string next_step_divergence() {
    try {
      simulation_->advance();
    } catch (const rouleau::DivergenceError& error) {
      std::printf("%s\n", error.what());
      return error.what();
    }
    return "";
  }

  std::filesystem::path folder_;
  std::unique_ptr<Simulation> simulation_;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST_F(Divergence, NanInTheFluidStateNamesTheUnknownAndTheNode) {
  // v at fluid node 17 becomes NaN: the step stops in the fluid stage naming that unknown.
  const auto state = simulation_->fluid().state();
  Kokkos::deep_copy(Kokkos::subview(state, 4 * 17 + 1), std::numeric_limits<double>::quiet_NaN());
  const std::string message = next_step_divergence();
  EXPECT_TRUE(contains(message, "diverged at step 2")) << message;
  EXPECT_TRUE(contains(message, "stage fluid")) << message;
  EXPECT_TRUE(contains(message, "unknown v of node 17 is nan")) << message;
}

TEST_F(Divergence, NanInACellsPositionStopsBeforeItsForcesReachTheFluid) {
  // A NaN coordinate of one node of cell 1: its elements' forces are NaN; the step stops
  // before spreading them, naming a node of cell 1 and its force.
  HostVectors x = host(cells().positions());
  const int node = first_node_of_second_cell() + 5;
  x(node, 2) = std::numeric_limits<double>::quiet_NaN();
  set_positions(x);
  const std::string message = next_step_divergence();
  EXPECT_TRUE(contains(message, "stage coupling: cell forces")) << message;
  EXPECT_TRUE(contains(message, "of cell 1 is NaN or Inf")) << message;
  EXPECT_TRUE(contains(message, "pN")) << message;
}

TEST_F(Divergence, AnInvertedCellElementIsNamedWithItsVolumeRatio) {
  // Node a of one element of cell 1 reflected through the plane of the element's other
  // three nodes: that tetrahedron is turned inside out (J = −1 for the reflection alone).
  // Its forces stay finite (the energy sees J only through J²), so only the element
  // check can stop the step.
  auto element_nodes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells().element_nodes());
  auto element_cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells().element_cell());
  int element = 0;
  while (element_cell(element) != 1) ++element;
  HostVectors x = host(cells().positions());
  double p[4][3];
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) p[a][i] = x(element_nodes(element, a), i);
  // n = (p2 − p1) × (p3 − p1); p0' = p0 − 2 ((p0 − p1)·n / |n|²) n
  double e1[3], e2[3], n[3];
  for (int i = 0; i < 3; ++i) e1[i] = p[2][i] - p[1][i], e2[i] = p[3][i] - p[1][i];
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  double along = 0.0, n2 = 0.0;
  for (int i = 0; i < 3; ++i) along += (p[0][i] - p[1][i]) * n[i], n2 += n[i] * n[i];
  for (int i = 0; i < 3; ++i) x(element_nodes(element, 0), i) = p[0][i] - 2.0 * along / n2 * n[i];
  set_positions(x);
  const auto worst = cells().most_compressed_element();
  EXPECT_LT(worst.volume_ratio, 0.0);
  EXPECT_EQ(worst.cell, 1);

  const std::string message = next_step_divergence();
  EXPECT_TRUE(contains(message, "stage move cells")) << message;
  EXPECT_TRUE(contains(message, "of cell 1 is inverted: its volume ratio J = det F is -")) << message;
}

TEST_F(Divergence, ACellThatLeftTheDomainIsNamedWithANodePosition) {
  // Cell 1 carried 30 μm up, through the moving wall at y = 10 μm (x and z are periodic).
  HostVectors x = host(cells().positions());
  const int first = first_node_of_second_cell();
  for (int node = first; node < first + cells().cell_node_count()[1]; ++node) x(node, 1) += 30.0;
  set_positions(x);
  const std::string message = next_step_divergence();
  EXPECT_TRUE(contains(message, "stage coupling: RKPM spread: cell 1 has left the fluid domain: its node " +
                                    std::to_string(first) + " is at"))
      << message;
}

TEST_F(Divergence, AHealthyStepPassesEveryCheck) {
  // The same scene untouched: the next steps pass, every element has J near 1.
  EXPECT_EQ(next_step_divergence(), "");
  const auto worst = cells().most_compressed_element();
  EXPECT_GT(worst.volume_ratio, 0.9);
  EXPECT_LT(worst.volume_ratio, 1.0 + 1e-12);
}

TEST(StateChecks, FirstNonFiniteRowFindsTheLowestBadRowOrNone) {
  // Against a plain serial scan, for NaN, +Inf and −Inf in a (row, 3) View and a flat one.
  Kokkos::View<double* [3]> vectors("vectors", 1000);
  Kokkos::View<double*> flat("flat", 1000);
  EXPECT_EQ(rouleau::first_non_finite_row(Kokkos::DefaultExecutionSpace(), vectors, "test"), -1);
  EXPECT_EQ(rouleau::first_non_finite_row(Kokkos::DefaultExecutionSpace(), flat, "test"), -1);
  const double bad[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity()};
  for (const double value : bad) {
    auto v = Kokkos::create_mirror_view(vectors);
    auto f = Kokkos::create_mirror_view(flat);
    Kokkos::deep_copy(v, 1.0);
    Kokkos::deep_copy(f, 1.0);
    v(731, 2) = value;
    v(402, 0) = value;
    f(999) = value;
    Kokkos::deep_copy(vectors, v);
    Kokkos::deep_copy(flat, f);
    EXPECT_EQ(rouleau::first_non_finite_row(Kokkos::DefaultExecutionSpace(), vectors, "test"), 402) << value;
    EXPECT_EQ(rouleau::first_non_finite_row(Kokkos::DefaultExecutionSpace(), flat, "test"), 999) << value;
    Kokkos::deep_copy(vectors, 0.0);
    Kokkos::deep_copy(flat, 0.0);
  }
}

}  // namespace
