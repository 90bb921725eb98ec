// The sub-grid film model of coupling/film_drainage.hpp on two capsules (spheres of radius
// 2.82 μm) 0.1 μm apart along x, with loads placed by hand on their film nodes: the load
// it reads, the squeeze resistance against the Reynolds solution for two spheres, the
// opening speed V = w T / ζ, its split (each capsule moved as a whole by ∓V/2 along the
// line of centres), the step's limit, and nothing at all beyond the open gap.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "cells/cells_from_case.hpp"
#include "config/load_case.hpp"
#include "coupling/film_drainage.hpp"
#include "temporary_folder.hpp"

namespace {

const double pi = 3.14159265358979323846;
const double diameter = 5.64, viscosity = 1.2e-3, open_gap = 1.0;

rouleau::CaseCells two_capsules(double gap) {
  const auto folder = rouleau::testing::temporary_folder("film_drainage");
  const std::string path = (folder / "case.toml").string();
  const double half = 0.5 * (diameter + gap);
  std::ofstream(path) << "[domain]\nlower_um = [-10, -5, -5]\nupper_um = [10, 5, 5]\nelements = [4, 2, 2]\n"
                      << "[time]\nmode = \"steady\"\n"
                      << "[[cells]]\nkind = \"capsule\"\ncenter_um = [" << -half << ", 0, 0]\n"
                      << "[[cells]]\nkind = \"capsule\"\ncenter_um = [" << half << ", 0, 0]\n";
  return rouleau::make_case_cells(rouleau::load_case(path), (folder / "meshes").string());
}

struct Outcome {
  rouleau::FilmDrainage::Film film;
  bool has_film = false;
  double speed_a = 0.0, speed_b = 0.0;  // each capsule's x-velocity (every node's the same)
  double spread = 0.0;                  // the largest deviation of a node from its capsule's velocity
};

// Each capsule pulled away from the other by `pull` [pN], spread evenly over its surface
// nodes within half the open gap of the other.
Outcome pulled_apart(const rouleau::CaseCells& cells, double pull, double dt) {
  const rouleau::CellPopulation& population = *cells.population;
  rouleau::FilmDrainage films(population, open_gap, viscosity);
  const int nodes = population.num_nodes();
  rouleau::CellPopulation::NodeVectors forces("forces", nodes), interpolated("interpolated", nodes),
      velocities("velocities", nodes);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.positions());
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_area_weights());
  auto cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.node_cell());
  auto f = Kokkos::create_mirror_view(forces);
  // Each capsule's centre (the mean of its nodes) and the loaded nodes: on the outer
  // surface, within half the open gap of the other sphere (|x − c_other| − R), so well
  // inside the film the model reads from the faceted surfaces.
  double centre_x[2] = {0.0, 0.0};
  int in_cell[2] = {0, 0};
  for (int n = 0; n < nodes; ++n) {
    centre_x[cell(n)] += x(n, 0);
    ++in_cell[cell(n)];
  }
  for (int c = 0; c < 2; ++c) centre_x[c] /= in_cell[c];
  const double half = 0.5 * diameter;
  const auto distance_to_other = [&](int n) {
    return std::hypot(x(n, 0) - centre_x[1 - cell(n)], x(n, 1), x(n, 2)) - half;
  };
  int counted[2] = {0, 0};
  for (int n = 0; n < nodes; ++n)
    if (w(n) > 0.0 && distance_to_other(n) < 0.5 * open_gap) ++counted[cell(n)];
  for (int n = 0; n < nodes; ++n) {
    f(n, 0) = f(n, 1) = f(n, 2) = 0.0;
    if (w(n) > 0.0 && distance_to_other(n) < 0.5 * open_gap)
      f(n, 0) = (cell(n) == 0 ? -pull : pull) / counted[cell(n)];  // away from the other
  }
  Kokkos::deep_copy(forces, f);
  films.add_opening_velocities(forces, interpolated, velocities, dt, 1.0);
  Outcome outcome;
  outcome.has_film = !films.films().empty();
  if (outcome.has_film) outcome.film = films.films()[0];
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), velocities);
  const int first_b = population.cell_first_node()[1];
  outcome.speed_a = v(0, 0);
  outcome.speed_b = v(first_b, 0);
  for (int n = 0; n < nodes; ++n) {
    const double expected = cell(n) == 0 ? outcome.speed_a : outcome.speed_b;
    outcome.spread = std::fmax(outcome.spread, std::fabs(v(n, 0) - expected) + std::fabs(v(n, 1)) + std::fabs(v(n, 2)));
  }
  return outcome;
}

TEST(FilmDrainage, TwoSpheresPulledApartOpenAtTheReynoldsSpeed) {
  const double gap = 0.1, pull = 0.5;
  const rouleau::CaseCells cells = two_capsules(gap);
  const Outcome o = pulled_apart(cells, pull, 1e-3);
  ASSERT_TRUE(o.has_film);
  // The load read back is the pull; the faceted spheres are a little apart beyond 0.1 μm.
  EXPECT_NEAR(o.film.load, pull, 1e-9);
  EXPECT_GE(o.film.smallest_gap, gap - 1e-9);
  EXPECT_LT(o.film.smallest_gap, gap + 0.03);
  // Two spheres of radius a: Reynolds with the reduced radius a/2, open at the open gap,
  // ζ = 6 π μ (a/2)² [1/h − 1/g_o − (g_o − h)/g_o²]. The capsules' 0.5 μm facets barely
  // resolve the film's pressure (its width √(a h) ≈ 0.5 μm), so within 35 %.
  const double h = o.film.smallest_gap, reduced = 0.25 * diameter;
  const double reynolds =
      6.0 * pi * viscosity * reduced * reduced * (1.0 / h - 1.0 / open_gap - (open_gap - h) / (open_gap * open_gap));
  std::printf("two spheres %.3f um apart: resistance %.4f pN s/um, Reynolds %.4f (%+.1f %%); opening %.4f um/s\n", h,
              o.film.resistance, reynolds, 100.0 * (o.film.resistance / reynolds - 1.0), o.film.opening_speed);
  EXPECT_NEAR(o.film.resistance / reynolds, 1.0, 0.35);
  // V = w T / ζ, split ∓V/2 along x, every node of a capsule alike.
  const double fade = (1.0 - h / open_gap) * (1.0 - h / open_gap);
  EXPECT_NEAR(o.film.opening_speed, fade * pull / o.film.resistance, 1e-12);
  EXPECT_GT(o.film.opening_speed, 0.0);
  EXPECT_NEAR(o.speed_a, -0.5 * o.film.opening_speed, 1e-12);
  EXPECT_NEAR(o.speed_b, 0.5 * o.film.opening_speed, 1e-12);
  EXPECT_LT(o.spread, 1e-12);
  // Pushed together instead: the film closes at the same speed.
  const Outcome pushed = pulled_apart(cells, -pull, 1e-3);
  EXPECT_NEAR(pushed.film.opening_speed, -o.film.opening_speed, 1e-12);
  // A step so long that the film would close in it: held to a quarter of the gap per step.
  const Outcome limited = pulled_apart(cells, -1e3 * pull, 1e-3);
  EXPECT_NEAR(limited.film.opening_speed, -0.25 * h / 1e-3, 1e-9);
}

TEST(FilmDrainage, NothingHappensBeyondTheOpenGap) {
  const rouleau::CaseCells cells = two_capsules(1.2);
  const Outcome o = pulled_apart(cells, 0.5, 1e-3);
  EXPECT_FALSE(o.has_film);
  EXPECT_EQ(o.speed_a, 0.0);
  EXPECT_EQ(o.speed_b, 0.0);
  EXPECT_EQ(o.spread, 0.0);
}

}  // namespace
