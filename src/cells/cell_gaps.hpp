#pragma once
// The gaps and contact areas between every pair of cells (kernels/surface_gap.hpp), for the
// aggregation diagnostics of the paper's scenes.
#include <Kokkos_Core.hpp>
#include <vector>

#include "cells/cell_population.hpp"

namespace rouleau {

struct CellPairGap {
  int a = 0, b = 0;           // the cells, a < b
  double gap = 0.0;           // smallest distance between their outer surfaces [μm]
  double contact_area = 0.0;  // the mean over both cells of their surface closer than the contact distance [μm²]
};

class CellGaps {
 public:
  // `contact_distance` [μm]: surface closer than this to the other cell counts as contact.
  CellGaps(const CellPopulation& population, double contact_distance);

  // Every pair (a < b), at the population's current positions. Distances are node to
  // triangle (a node of each cell to the nearest outer-surface triangle of the other,
  // both ways), so the gap is exact for the meshes' piecewise-flat surfaces. Brute force
  // over the two cells' surfaces: O(nodes × triangles) per pair.
  std::vector<CellPairGap> measure() const;

 private:
  // The distance from each of cell a's nodes to cell b's surface, into distance_.
  void node_distances(int a, int b) const;

  const CellPopulation& population_;
  double contact_distance_;
  std::vector<int> first_triangle_, triangle_count_;  // per cell
  Kokkos::View<double*> distance_;                    // scratch, the largest cell's node count
};

}  // namespace rouleau
