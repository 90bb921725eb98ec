// The sub-grid film model of coupling/film_drainage.hpp on two capsules (spheres of radius
// 2.82 μm) 0.1 μm apart along x, with loads placed by hand on their film nodes: the load
// it reads, the squeeze resistance against the Reynolds solution for two spheres, the
// opening speed V = w T / ζ, its split (each capsule moved as a whole by ∓V/2 along the
// line of centres), the step's limit, and nothing at all beyond the open gap; and the
// deforming films' node velocities on the same pair (the capsules move apart as wholes, at
// about the rigid films' speed, and only the films' nodes and those below them move
// otherwise; linear in the loads, with positive power, limited by one factor for all).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

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
  std::vector<double> velocity;         // every node's, x, y, z
  double power = 0.0;                   // Σ f · (v − v_interpolated) [pN μm/s]
  double speed_a = 0.0, speed_b = 0.0;  // each capsule's x-velocity (every node's the same)
  double spread = 0.0;                  // the largest deviation of a node from its capsule's velocity
};

// Each capsule pulled away from the other by `pull` [pN], spread evenly over its surface
// nodes within half the open gap of the other.
Outcome pulled_apart(const rouleau::CaseCells& cells, double pull, double dt,
                     rouleau::FilmModel model = rouleau::FilmModel::rigid) {
  const rouleau::CellPopulation& population = *cells.population;
  rouleau::FilmDrainage films(population, open_gap, viscosity, model);
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
  for (int n = 0; n < nodes; ++n)
    for (int i = 0; i < 3; ++i) {
      outcome.velocity.push_back(v(n, i));
      outcome.power += f(n, i) * v(n, i);
    }
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

TEST(FilmDrainage, DeformingFilmsMoveTheirFacesApartWhenPulled) {
  const rouleau::CaseCells cells = two_capsules(0.1);
  const rouleau::CellPopulation& population = *cells.population;
  const double pull = 0.5, dt = 1e-3;
  const Outcome o = pulled_apart(cells, pull, dt, rouleau::FilmModel::deforming);
  const Outcome rigid = pulled_apart(cells, pull, dt, rouleau::FilmModel::rigid);
  ASSERT_TRUE(o.has_film);
  std::printf("deforming film: load %.4f pN, resistance %.4f pN s/um, mean opening %.4f um/s, power %.4g\n",
              o.film.load, o.film.resistance, o.film.opening_speed, o.power);
  EXPECT_GT(o.film.opening_speed, 0.0);
  EXPECT_GT(o.power, 0.0);  // the loads do work on the films, which dissipate it
  // Its opening mode reads the load as rigid films do (w̄ T) against the same resistance.
  const double fade = (1.0 - o.film.smallest_gap / open_gap) * (1.0 - o.film.smallest_gap / open_gap);
  EXPECT_NEAR(o.film.load, fade * rigid.film.load, 1e-3 * fade * rigid.film.load);  // axis: x within facets
  EXPECT_NEAR(o.film.resistance, rigid.film.resistance, 1e-9 * rigid.film.resistance);
  // Nodes beyond the open gap plus the membrane's depth (0.6 μm) from the other capsule move
  // with their capsule's opening alone: one velocity per capsule, along x, away from the
  // other, the two opposite. The pair opens at about the rigid films' speed (within a factor
  // of 2: the face modes share the load). The loaded nodes (outer surface, within half the
  // open gap) move away from the other capsule along x on the (area) mean; not each one:
  // where the film is thinnest its plasma follows slowest, and the faces may dimple there,
  // as draining films do.
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.positions());
  auto cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.node_cell());
  const double centre_distance = diameter + 0.1;
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_area_weights());
  int far_nodes[2] = {0, 0};
  double far_velocity[2][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}, far_spread = 0.0, loaded_away = 0.0;
  for (int n = 0; n < population.num_nodes(); ++n) {
    const double vx = o.velocity[3 * n];
    const double other_x = cell(n) == 0 ? 0.5 * centre_distance : -0.5 * centre_distance;
    const double distance = std::hypot(x(n, 0) - other_x, x(n, 1), x(n, 2)) - 0.5 * diameter;
    const double away = cell(n) == 0 ? -vx : vx;
    if (w(n) > 0.0 && distance < 0.5 * open_gap) loaded_away += w(n) * away;
    if (distance < open_gap + 0.6 + 0.05) continue;
    double* v = far_velocity[cell(n)];
    if (far_nodes[cell(n)]++ == 0)
      for (int i = 0; i < 3; ++i) v[i] = o.velocity[3 * n + i];
    for (int i = 0; i < 3; ++i) far_spread = std::fmax(far_spread, std::fabs(o.velocity[3 * n + i] - v[i]));
  }
  const double relative_speed = far_velocity[1][0] - far_velocity[0][0];
  std::printf("deforming film: the capsules part at %.4f um/s (rigid films: %.4f um/s)\n", relative_speed,
              rigid.film.opening_speed);
  EXPECT_GT(far_nodes[0], 20);
  EXPECT_GT(far_nodes[1], 20);
  EXPECT_LT(far_spread, 1e-9 * std::fabs(relative_speed));
  EXPECT_LT(far_velocity[0][0], 0.0);
  EXPECT_GT(far_velocity[1][0], 0.0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(far_velocity[0][i], -far_velocity[1][i], 1e-9 * relative_speed);  // apart, along the film's axis
    if (i > 0) EXPECT_LT(std::fabs(far_velocity[1][i]), 0.01 * relative_speed);   // which is x, within facets
  }
  EXPECT_GT(relative_speed, 0.5 * rigid.film.opening_speed);
  EXPECT_LT(relative_speed, 2.0 * rigid.film.opening_speed);
  EXPECT_GT(loaded_away, 0.0);
  // Linear in the loads: pushed instead, every velocity reverses.
  const Outcome pushed = pulled_apart(cells, -pull, dt, rouleau::FilmModel::deforming);
  double largest = 0.0;
  for (std::size_t k = 0; k < o.velocity.size(); ++k) {
    largest = std::fmax(largest, std::fabs(o.velocity[k]));
    EXPECT_NEAR(pushed.velocity[k], -o.velocity[k], 1e-12 * (1.0 + std::fabs(o.velocity[k])));
  }
  // A load so large that a film node would cross its gap in one step: every speed is scaled
  // by one factor, below 1.
  const double factor = 1e4;
  const Outcome limited = pulled_apart(cells, factor * pull, dt, rouleau::FilmModel::deforming);
  double scale = 0.0;
  for (std::size_t k = 0; k < o.velocity.size(); ++k)
    if (std::fabs(o.velocity[k]) > 1e-3 * largest) {
      const double ratio = limited.velocity[k] / (factor * o.velocity[k]);
      if (scale == 0.0) scale = ratio;
      EXPECT_NEAR(ratio, scale, 1e-9);
    }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(scale, 1.0);
  // Beyond the open gap, nothing.
  const rouleau::CaseCells apart = two_capsules(1.2);
  const Outcome far = pulled_apart(apart, pull, dt, rouleau::FilmModel::deforming);
  EXPECT_FALSE(far.has_film);
  for (const double v : far.velocity) EXPECT_EQ(v, 0.0);
}

}  // namespace
