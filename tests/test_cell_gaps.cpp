// Gaps and contact areas between cells (kernels/surface_gap.hpp, src/cells/cell_gaps): the
// point–triangle distance against a plain serial reference by another construction, and
// two capsules at a known separation against the exact sphere–sphere gap and the contact
// area of two spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "cells/cell_gaps.hpp"
#include "cells/cells_from_case.hpp"
#include "config/load_case.hpp"
#include "kernels/surface_gap.hpp"
#include "test_helpers.hpp"
#include "temporary_folder.hpp"

namespace {

// Reference: the distance to the triangle's plane when the projection falls inside (by
// barycentric coordinates from a 2×2 solve), else the least distance to its three edges
// (each a segment: the clamped projection).
double reference_distance(const double p[3], const double a[3], const double b[3], const double c[3]) {
  const auto segment = [&](const double s[3], const double t[3]) {
    double d[3], w[3], dd = 0.0, wd = 0.0;
    for (int i = 0; i < 3; ++i) {
      d[i] = t[i] - s[i];
      w[i] = p[i] - s[i];
      dd += d[i] * d[i];
      wd += w[i] * d[i];
    }
    const double u = std::clamp(wd / dd, 0.0, 1.0);
    double r2 = 0.0;
    for (int i = 0; i < 3; ++i) r2 += (w[i] - u * d[i]) * (w[i] - u * d[i]);
    return std::sqrt(r2);
  };
  double e1[3], e2[3], w[3];
  for (int i = 0; i < 3; ++i) {
    e1[i] = b[i] - a[i];
    e2[i] = c[i] - a[i];
    w[i] = p[i] - a[i];
  }
  // [e1·e1 e1·e2; e1·e2 e2·e2] (s, t) = (w·e1, w·e2)
  const double g11 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2], g12 = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2],
               g22 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
  const double r1 = w[0] * e1[0] + w[1] * e1[1] + w[2] * e1[2], r2 = w[0] * e2[0] + w[1] * e2[1] + w[2] * e2[2];
  const double det = g11 * g22 - g12 * g12;
  const double s = (r1 * g22 - r2 * g12) / det, t = (g11 * r2 - g12 * r1) / det;
  if (s >= 0.0 && t >= 0.0 && s + t <= 1.0) {
    double d2 = 0.0;
    for (int i = 0; i < 3; ++i) d2 += (w[i] - s * e1[i] - t * e2[i]) * (w[i] - s * e1[i] - t * e2[i]);
    return std::sqrt(d2);
  }
  return std::min({segment(a, b), segment(b, c), segment(c, a)});
}

TEST(CellGaps, PointTriangleDistanceMatchesAPlainReference) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  double worst = 0.0;
  for (int trial = 0; trial < 20000; ++trial) {
    double p[3], a[3], b[3], c[3];
    for (int i = 0; i < 3; ++i) {
      p[i] = u(rng);
      a[i] = u(rng);
      b[i] = u(rng);
      c[i] = u(rng);
    }
    const double kernel = std::sqrt(rouleau::point_triangle_distance_squared(p, a, b, c));
    worst = std::max(worst, std::abs(kernel - reference_distance(p, a, b, c)));
  }
  std::printf("point-triangle distance, 20000 random cases: largest difference from the reference %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

rouleau::CaseConfig two_capsules(double gap) {
  const auto folder = rouleau::testing::temporary_folder("cell_gaps");
  const std::string path = (folder / "case.toml").string();
  // Capsules of diameter 5.64 μm ("paper" resolution), centres 5.64 + gap apart along x.
  const double half = 0.5 * (5.64 + gap);
  std::ofstream(path) << "[domain]\nlower_um = [-10, -5, -5]\nupper_um = [10, 5, 5]\nelements = [4, 2, 2]\n"
                      << "[time]\nmode = \"steady\"\n"
                      << "[[cells]]\nkind = \"capsule\"\ncenter_um = [" << -half << ", 0, 0]\n"
                      << "[[cells]]\nkind = \"capsule\"\ncenter_um = [" << half << ", 0, 0]\n";
  return rouleau::load_case(path);
}

TEST(CellGaps, TwoCapsulesAtAKnownSeparation) {
  // The meshed spheres' facets lie inside the spheres, so the measured gap is at least the
  // exact one and exceeds it by at most two sagittas h²/(8R). The contact area (surface
  // within r0 = 0.25 μm of the other cell) of two spheres of radius R at gap g: the surfaces
  // part as g + R θ², so contact reaches θ² = (r0 − g)/R, an area π R (r0 − g) on each.
  for (double gap : {0.1, 0.5}) {
    const rouleau::CaseConfig config = two_capsules(gap);
    const rouleau::CaseCells cells =
        rouleau::make_case_cells(config, rouleau::testing::temporary_folder("cell_gaps_meshes").string());
    const rouleau::CellGaps gaps(*cells.population, 0.25);
    const auto pairs = gaps.measure();
    ASSERT_EQ(pairs.size(), 1u);
    const double radius = 0.5 * 5.64;
    const double contact = gap < 0.25 ? 3.14159265358979 * radius * (0.25 - gap) : 0.0;
    std::printf("two capsules %.2f um apart: measured gap %.4f um; contact area %.3f um^2 (two spheres: %.3f)\n", gap,
                pairs[0].gap, pairs[0].contact_area, contact);
    EXPECT_GE(pairs[0].gap, gap - 1e-9);
    EXPECT_LT(pairs[0].gap, gap + 0.03);
    if (contact > 0.0) EXPECT_NEAR(pairs[0].contact_area, contact, 0.15 * contact);  // measured +8 %
    else EXPECT_EQ(pairs[0].contact_area, 0.0);
  }
}

// The pruned search (patches of triangles with bounding spheres) against a plain serial
// loop over every triangle, on two capsules whose nodes are displaced at random by up to
// ±0.3 μm (rough, folded surfaces, so that many patches overlap), at gaps from contact to
// beyond the patches' size: the gap and the contact area agree to round-off.
TEST(CellGaps, PrunedSearchEqualsEveryTriangleOnRoughSurfaces) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> shake(-0.3, 0.3);
  for (double gap : {0.05, 0.4, 3.0}) {
    const rouleau::CaseConfig config = two_capsules(gap);
    const rouleau::CaseCells cells =
        rouleau::make_case_cells(config, rouleau::testing::temporary_folder("cell_gaps_rough").string());
    rouleau::CellPopulation& population = *cells.population;
    Kokkos::View<double* [3], Kokkos::HostSpace> x("positions", population.num_nodes());
    Kokkos::deep_copy(x, population.positions());
    for (std::size_t n = 0; n < x.extent(0); ++n)
      for (int i = 0; i < 3; ++i) x(n, i) += shake(rng);
    population.set_positions(x);
    const double contact_distance = 0.25;
    const auto pairs = rouleau::CellGaps(population, contact_distance).measure();
    ASSERT_EQ(pairs.size(), 1u);

    // Serial reference: every surface node of one cell against every triangle of the other.
    auto triangles = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_triangles());
    auto triangle_cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.triangle_cell());
    auto weights = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_area_weights());
    double gap_reference = INFINITY, area_reference = 0.0;
    for (int from = 0; from < 2; ++from) {
      const int first = population.cell_first_node()[from], count = population.cell_node_count()[from];
      for (int n = first; n < first + count; ++n) {
        if (!(weights(n) > 0.0)) continue;
        const double p[3] = {x(n, 0), x(n, 1), x(n, 2)};
        double nearest = INFINITY;
        for (std::size_t t = 0; t < triangles.extent(0); ++t) {
          if (triangle_cell(t) == from) continue;
          double corner[3][3];
          for (int v = 0; v < 3; ++v)
            for (int i = 0; i < 3; ++i) corner[v][i] = x(triangles(t, v), i);
          nearest = std::min(nearest, reference_distance(p, corner[0], corner[1], corner[2]));
        }
        gap_reference = std::min(gap_reference, nearest);
        if (nearest < contact_distance) area_reference += 0.5 * weights(n);
      }
    }
    std::printf("rough capsules %.2f um apart: gap %.6f um (every triangle: %.6f), contact area %.4f um^2 (%.4f)\n",
                gap, pairs[0].gap, gap_reference, pairs[0].contact_area, area_reference);
    EXPECT_NEAR(pairs[0].gap, gap_reference, 1e-12);
    EXPECT_NEAR(pairs[0].contact_area, area_reference, 1e-9 * (1.0 + area_reference));
  }
}

}  // namespace
