// Reynolds' film equation of cells/film_lubrication.hpp against exact lubrication
// resistances: a sphere near a plane (axisymmetric Reynolds solution with the film open
// where it reaches the open gap) and a square film of uniform gap between parallel plates
// (the Poisson problem's series solution), with the error falling under refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "cells/film_lubrication.hpp"

namespace {

const double pi = 3.14159265358979323846;

// A square patch [−half, half]² in the plane z = 0, n × n squares each cut into two
// triangles, with gap(x, y) at each node.
template <class Gap>
rouleau::FilmPatch square_patch(double half, int n, Gap gap) {
  rouleau::FilmPatch film;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -half + 2.0 * half * i / n, y = -half + 2.0 * half * j / n;
      film.points.push_back({x, y, 0.0});
      film.gap.push_back(gap(x, y));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      film.triangles.push_back({a, b, d});
      film.triangles.push_back({a, d, c});
    }
  return film;
}

TEST(FilmLubrication, SphereNearAPlaneMatchesReynoldsAxisymmetricSolution) {
  // Gap h + r²/(2R) (a sphere of radius R at h from the plane), open at g_c:
  // p = 3 μ V R (1/g² − 1/g_c²), F / V = 6 π μ R² [1/h − 1/g_c − (g_c − h)/g_c²].
  const double radius = 1.0, h = 0.05, open_gap = 0.5, viscosity = 1.2e-3;
  const double exact =
      6.0 * pi * viscosity * radius * radius * (1.0 / h - 1.0 / open_gap - (open_gap - h) / (open_gap * open_gap));
  double previous_error = INFINITY;
  for (const int n : {40, 80, 160}) {
    const auto film = square_patch(1.2, n, [&](double x, double y) { return h + (x * x + y * y) / (2.0 * radius); });
    const double resistance = rouleau::squeeze_resistance(film, viscosity, open_gap);
    const double error = std::fabs(resistance / exact - 1.0);
    std::printf("sphere near a plane, %d x %d: F/V = %.5f pN s/um, exact %.5f, error %.2f %%\n", n, n, resistance,
                exact, 100.0 * error);
    EXPECT_LT(error, previous_error);
    previous_error = error;
  }
  EXPECT_LT(previous_error, 0.02);
}

TEST(FilmLubrication, SquareFilmOfUniformGapMatchesTheSeriesSolution) {
  // Parallel plates h apart, a square film of side s open at its edge:
  // F / V = (12 μ / h³) c s⁴, c = (64/π⁶) Σ_{m,n odd} 1 / (m² n² (m² + n²)) = 0.0351443.
  const double h = 0.1, side = 2.0, viscosity = 1.2e-3;
  const double exact = 12.0 * viscosity / (h * h * h) * 0.0351442533 * std::pow(side, 4);
  double previous_error = INFINITY;
  for (const int n : {16, 32, 64}) {
    const auto film = square_patch(0.5 * side, n, [&](double, double) { return h; });
    const double error = std::fabs(rouleau::squeeze_resistance(film, viscosity, 1.0) / exact - 1.0);
    std::printf("square film, %d x %d: error %.3f %%\n", n, n, 100.0 * error);
    EXPECT_LT(error, previous_error);
    previous_error = error;
  }
  EXPECT_LT(previous_error, 0.005);
}

TEST(FilmLubrication, SquareFilmTiltingMatchesTheSeriesSolution) {
  // The same film closing at the rate V(x) = x (the faces tilting about the y axis):
  // −∇²p = (12 μ / h³) x, p = 0 at the edge; with u = x + s/2 and the sine series on [0, s]²,
  // Z_xx = ∫ p x dA = (12 μ / h³) (16 s⁶ / π⁶) Σ_{m even, n odd} 1 / (m² n² (m² + n²)).
  // The modes 1 and x are orthogonal in the film's dissipation (Z_1x = 0 by symmetry), and
  // Z_11 is the uniform closing's resistance.
  const double h = 0.1, side = 2.0, viscosity = 1.2e-3;
  double sum = 0.0;
  for (int m = 2; m < 4000; m += 2)
    for (int n = 1; n < 4000; n += 2) sum += 1.0 / (double(m) * m * n * n * (double(m) * m + double(n) * n));
  const double exact = 12.0 * viscosity / (h * h * h) * 16.0 * std::pow(side, 6) / std::pow(pi, 6) * sum;
  double previous_error = INFINITY;
  for (const int n : {16, 32, 64}) {
    const auto film = square_patch(0.5 * side, n, [&](double, double) { return h; });
    std::vector<double> uniform(film.points.size(), 1.0), tilt(film.points.size());
    for (std::size_t p = 0; p < film.points.size(); ++p) tilt[p] = film.points[p][0];
    const auto z = rouleau::squeeze_resistances(film, viscosity, 1.0, {uniform, tilt});
    const double error = std::fabs(z[1][1] / exact - 1.0);
    std::printf("square film tilting, %d x %d: Z_xx = %.6f pN s um, exact %.6f, error %.3f %%\n", n, n, z[1][1],
                exact, 100.0 * error);
    EXPECT_LT(error, previous_error);
    previous_error = error;
    EXPECT_NEAR(z[0][0], rouleau::squeeze_resistance(film, viscosity, 1.0), 1e-12 * z[0][0]);
    EXPECT_NEAR(z[0][1], z[1][0], 1e-9 * z[0][0]);
    EXPECT_LT(std::fabs(z[0][1]), 1e-9 * z[0][0]);
  }
  EXPECT_LT(previous_error, 0.005);
}

TEST(FilmLubrication, AnOpenOrBadFilmIsRefused) {
  // Every node beyond the open gap: no film, no resistance.
  EXPECT_EQ(rouleau::squeeze_resistance(square_patch(1.0, 4, [](double, double) { return 2.0; }), 1e-3, 1.0), 0.0);
  auto touching = square_patch(1.0, 4, [](double, double) { return 0.1; });
  touching.gap[7] = 0.0;
  EXPECT_THROW(rouleau::squeeze_resistance(touching, 1e-3, 1.0), std::invalid_argument);
  auto broken = square_patch(1.0, 4, [](double, double) { return 0.1; });
  broken.triangles[3][1] = 99;
  EXPECT_THROW(rouleau::squeeze_resistance(broken, 1e-3, 1.0), std::invalid_argument);
}

}  // namespace
