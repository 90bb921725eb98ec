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
  // both ways), so the gap is exact for the meshes' piecewise-flat surfaces. Each node
  // visits only the patches of 8 to 16 nearby triangles that may hold its nearest point
  // (kernels/surface_gap.hpp), with the same result as a loop over every triangle.
  std::vector<CellPairGap> measure() const;
  // The surface patches' bounding spheres at the current positions: once after the cells
  // moved, before node_distances_to (measure() does it itself).
  void locate_surfaces() const;
  // The distance from each of cell a's nodes to cell b's outer surface, at the positions
  // of the last locate_surfaces(), in a's node order, on the host (as measure() finds it;
  // nodes off a's outer surface are not measured and hold +infinity).
  std::vector<double> node_distances_to(int a, int b) const;

 private:
  // The distance from each of cell a's nodes to cell b's surface, into distance_.
  void node_distances(int a, int b) const;

  const CellPopulation& population_;
  double contact_distance_;
  std::vector<int> first_triangle_, triangle_count_;  // per cell
  std::vector<int> first_patch_, patch_count_;        // per cell: its triangles' patches
  Kokkos::View<int*> patch_offsets_;                  // patch q: patch_triangles_[offsets(q), offsets(q + 1))
  Kokkos::View<int*> patch_triangles_;                // the triangles, patch by patch
  Kokkos::View<double* [4]> patch_bounds_;            // bounding sphere per patch, at measure()
  Kokkos::View<double*> distance_;                    // scratch, the largest cell's node count
};

}  // namespace rouleau
