// The rim band of cells/rim_band.hpp (the paper's Fig. 7: "the interaction forces act
// mainly at the rims") on a red cell turned so that its axis lies along y, against a plain
// reference that uses the known axis, and its force share on forces placed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <vector>

#include "cells/cells_from_case.hpp"
#include "cells/rim_band.hpp"
#include "config/load_case.hpp"
#include "temporary_folder.hpp"

namespace {

// One normal cell (the coarse mesh) at (1, 2, 3), its axis turned from z to y.
rouleau::CaseCells turned_cell() {
  const auto folder = rouleau::testing::temporary_folder("rim_band");
  const std::string path = (folder / "case.toml").string();
  std::ofstream(path) << "[domain]\nlower_um = [-8, -8, -8]\nupper_um = [8, 8, 8]\nelements = [2, 2, 2]\n"
                      << "[time]\nmode = \"steady\"\n[cell_kinds.normal]\nresolution = \"coarse\"\n"
                      << "[[cells]]\nkind = \"normal\"\ncenter_um = [1, 2, 3]\norientation_deg = [90, 0, 0]\n";
  return rouleau::make_case_cells(rouleau::load_case(path), (folder / "meshes").string());
}

TEST(RimBand, TheBandIsTheSurfaceNearTheCrestsAboutTheCellsAxis) {
  const rouleau::CaseCells cells = turned_cell();
  const rouleau::CellPopulation& population = *cells.population;
  const rouleau::RimBand band(population);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.reference_positions());
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_area_weights());
  const int nodes = static_cast<int>(x.extent(0));
  // Reference: heights along y from the area-weighted centroid's y.
  double area = 0.0, centroid_y = 0.0;
  for (int n = 0; n < nodes; ++n) {
    area += w(n);
    centroid_y += w(n) * x(n, 1);
  }
  centroid_y /= area;
  double largest = 0.0;
  for (int n = 0; n < nodes; ++n)
    if (w(n) > 0.0) largest = std::fmax(largest, std::fabs(x(n, 1) - centroid_y));
  double band_area = 0.0;
  int mismatches = 0, band_nodes = 0;
  for (int n = 0; n < nodes; ++n) {
    const bool expected = w(n) > 0.0 && std::fabs(x(n, 1) - centroid_y) >= 0.75 * largest;
    if (expected) band_area += w(n);
    band_nodes += band.in_band()[n];
    // Nodes within round-off of the band's edge may go either way.
    const bool at_edge = std::fabs(std::fabs(x(n, 1) - centroid_y) - 0.75 * largest) < 1e-9;
    if (!at_edge && expected != bool(band.in_band()[n])) ++mismatches;
  }
  std::printf("rim band: %d nodes of %d, area share %.3f (reference %.3f), largest height %.3f um\n", band_nodes,
              nodes, band.area_share(), band_area / area, largest);
  EXPECT_EQ(mismatches, 0);
  EXPECT_NEAR(band.area_share(), band_area / area, 1e-9);
  EXPECT_GT(band.area_share(), 0.2);  // the crests of both faces, neither all nor nothing
  EXPECT_LT(band.area_share(), 0.7);
  EXPECT_NEAR(largest, 1.28, 0.1);  // the Evans–Fung cell's half-thickness at its crest

  // Forces on the band only: share 1; off it only: 0; |f| in proportion to the area
  // weights: the band's area share; none: 0.
  std::vector<double> on(3 * nodes, 0.0), off(3 * nodes, 0.0), by_area(3 * nodes, 0.0);
  for (int n = 0; n < nodes; ++n) {
    (band.in_band()[n] ? on : off)[3 * n + 2] = 1.5;
    by_area[3 * n] = 0.6 * w(n);
    by_area[3 * n + 1] = -0.8 * w(n);
  }
  EXPECT_DOUBLE_EQ(band.force_share(on.data()), 1.0);
  EXPECT_DOUBLE_EQ(band.force_share(off.data()), 0.0);
  EXPECT_NEAR(band.force_share(by_area.data()), band.area_share(), 1e-12);
  EXPECT_DOUBLE_EQ(band.force_share(std::vector<double>(3 * nodes, 0.0).data()), 0.0);
}

}  // namespace
