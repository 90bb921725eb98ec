// The vessel wall's repulsion of cell surface nodes (kernels/wall_repulsion.hpp): the force
// against minus the gradient of the energy, against a plain serial reference on the exact
// profile, its range and contact pressure, and a node pushed at the wall coming to rest at
// the distance where the two forces balance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "coupling/wall_repulsion.hpp"
#include "vessel_profiles.hpp"

namespace rouleau {
namespace {

using NodeVectors = WallRepulsion::NodeVectors;

constexpr double pressure = 2.0, range = 0.5;

// Points within the range of the wall (d from −0.1 to 0.6 μm), all along the vessel, with
// area weights between 0.05 and 0.2 μm².
void random_nodes(const VesselProfile& profile, int count, NodeVectors& positions, Kokkos::View<double*>& weights) {
  positions = testing::points_near_wall(profile, count, -0.1, 0.6, 0.3, 7);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> area(0.05, 0.2);
  weights = Kokkos::View<double*>("weights", count);
  auto w = Kokkos::create_mirror_view(weights);
  for (int n = 0; n < count; ++n) w(n) = area(rng);
  Kokkos::deep_copy(weights, w);
}

TEST(WallRepulsion, ForceIsMinusTheGradientOfTheEnergy) {
  // Forces from the forces-only launch against central differences of the energies of the
  // forces-and-energy launch: both paths of the kernel.
  const VesselProfile profile = testing::small_contraction();
  const WallRepulsion wall(profile, pressure, range);
  NodeVectors positions, forces("forces", 200);
  Kokkos::View<double*> weights;
  random_nodes(profile, 200, positions, weights);
  wall.compute_forces(positions, weights, forces);  // the coupled step's path; energies below
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), positions);
  auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), forces);
  // Central differences of the total energy, one node and one direction at a time.
  NodeVectors shifted("shifted", 200), scratch("scratch", 200);
  double worst = 0.0, largest = 0.0;
  const double eps = 1e-6;
  for (int n = 0; n < 200; n += 7)
    for (int c = 0; c < 3; ++c) {
      auto moved = Kokkos::create_mirror_view(shifted);
      Kokkos::deep_copy(moved, x);
      moved(n, c) += eps;
      Kokkos::deep_copy(shifted, moved);
      const double plus = wall.compute_forces_and_energy(shifted, weights, scratch);
      moved(n, c) -= 2 * eps;
      Kokkos::deep_copy(shifted, moved);
      const double minus = wall.compute_forces_and_energy(shifted, weights, scratch);
      const double gradient = (plus - minus) / (2 * eps);
      worst = std::max(worst, std::abs(f(n, c) + gradient));
      largest = std::max(largest, std::abs(f(n, c)));
    }
  std::printf("wall repulsion: |f + dE/dx| <= %.2e against forces up to %.3f pN\n", worst, largest);
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(worst, 1e-6 * largest);
}

TEST(WallRepulsion, MatchesAPlainSerialReferenceOnTheExactProfile) {
  // f = p_w A s² (R'(x), −y/r, −z/r), s = 1 − (R(x) − r)/d0, with R and R' from the exact
  // profile (R' by central differences) instead of the kernel's table (cubic Hermite), for
  // cosine and conical transitions (whose corners are knots of the table).
  for (VesselTransition transition : {VesselTransition::cosine, VesselTransition::cone}) {
    VesselProfile profile = testing::small_contraction();
    profile.transition = transition;
    const WallRepulsion wall(profile, pressure, range);
    NodeVectors positions, forces("forces", 500);
    Kokkos::View<double*> weights;
    random_nodes(profile, 500, positions, weights);
    wall.compute_forces_and_energy(positions, weights, forces);
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), positions);
    auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), weights);
    auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), forces);
    double worst = 0.0;
    int pushed = 0;
    for (int n = 0; n < 500; ++n) {
      const double radius = vessel_radius(profile, x(n, 0));
      const double slope = (vessel_radius(profile, x(n, 0) + 1e-6) - vessel_radius(profile, x(n, 0) - 1e-6)) / 2e-6;
      const double r = std::hypot(x(n, 1), x(n, 2)), d = radius - r;
      double expected[3] = {0, 0, 0};
      if (d < range) {
        const double s = 1.0 - d / range, magnitude = pressure * w(n) * s * s;
        expected[0] = magnitude * slope;
        expected[1] = -magnitude * x(n, 1) / r;
        expected[2] = -magnitude * x(n, 2) / r;
        ++pushed;
      }
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(f(n, c) - expected[c]));
    }
    std::printf("wall repulsion (%s transitions): %d of 500 nodes pushed; kernel vs serial reference: %.2e pN\n",
                transition == VesselTransition::cosine ? "cosine" : "conical", pushed, worst);
    EXPECT_GT(pushed, 300);
    EXPECT_LT(worst, 1e-7);
  }
}

TEST(WallRepulsion, ActsOnlyWithinItsRangeWithThePressureAtContact) {
  const VesselProfile tube = testing::tube(3.0, 10.0);
  const WallRepulsion wall(tube, pressure, range);
  // Nodes at d = 0.6, 0.5, 0.25, 0 from the wall, weight 0.1 μm²; and one with no weight.
  const double gaps[5] = {0.6, 0.5, 0.25, 0.0, 0.0};
  NodeVectors positions("positions", 5), forces("forces", 5);
  Kokkos::View<double*> weights("weights", 5);
  auto x = Kokkos::create_mirror_view(positions);
  auto w = Kokkos::create_mirror_view(weights);
  for (int n = 0; n < 5; ++n) {
    x(n, 0) = 5.0;
    x(n, 1) = 3.0 - gaps[n];
    x(n, 2) = 0.0;
    w(n) = n < 4 ? 0.1 : 0.0;
  }
  Kokkos::deep_copy(positions, x);
  Kokkos::deep_copy(weights, w);
  const double energy = wall.compute_forces_and_energy(positions, weights, forces);
  auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), forces);
  EXPECT_EQ(f(0, 1), 0.0);
  EXPECT_EQ(f(1, 1), 0.0);
  EXPECT_NEAR(f(2, 1), -pressure * 0.1 * 0.25, 1e-12);  // s = 1/2
  EXPECT_NEAR(f(3, 1), -pressure * 0.1, 1e-12);         // contact: p_w A
  EXPECT_EQ(f(4, 1), 0.0);
  for (int n = 0; n < 5; ++n) EXPECT_EQ(f(n, 0), 0.0);  // a straight wall pushes radially only
  // E = p_w A d0 s³/3 summed: s = 1/2 and 1.
  EXPECT_NEAR(energy, pressure * 0.1 * range * (0.125 + 1.0) / 3.0, 1e-12);
}

TEST(WallRepulsion, ANodePushedAtTheWallStopsWhereTheForcesBalance) {
  // A node of area weight A pushed outward by a constant F < p_w A, moving with the
  // overdamped mobility 1/ζ, comes to rest at d* = d0 (1 − √(F/(p_w A))), inside the lumen.
  const VesselProfile tube = testing::tube(3.0, 10.0);
  const WallRepulsion wall(tube, pressure, range);
  const double area = 0.1, push = 0.5 * pressure * area, mobility_times_step = 0.05;  // [μm/pN]
  NodeVectors position("position", 1), force("force", 1);
  Kokkos::View<double*> weight("weight", 1);
  Kokkos::deep_copy(weight, area);
  auto x = Kokkos::create_mirror_view(position);
  x(0, 0) = 5.0;
  x(0, 1) = 0.0;
  x(0, 2) = 2.0;  // 1 μm from the wall
  double closest = 1.0;
  for (int step = 0; step < 4000; ++step) {
    Kokkos::deep_copy(position, x);
    wall.compute_forces_and_energy(position, weight, force);
    auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), force);
    x(0, 2) += mobility_times_step * (push + f(0, 2));
    closest = std::min(closest, 3.0 - x(0, 2));
  }
  const double expected = range * (1.0 - std::sqrt(push / (pressure * area)));
  std::printf("pushed node: rests %.6f um from the wall, expected %.6f um; closest %.6f um\n", 3.0 - x(0, 2), expected,
              closest);
  EXPECT_NEAR(3.0 - x(0, 2), expected, 1e-6);
  EXPECT_GT(closest, 0.0);
}

}  // namespace
}  // namespace rouleau
