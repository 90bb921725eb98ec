#include "fluid/fluid_matrix.hpp"

#include <algorithm>
#include <vector>

namespace rouleau {

FluidMatrixGraph build_fluid_matrix_graph(const FluidMesh& mesh) {
  auto conn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_dof_nodes);
  const int nodes = mesh.num_dof_nodes, npe = mesh.nodes_per_element;
  std::vector<std::vector<int>> neighbors(nodes);
  for (int e = 0; e < mesh.num_elements; ++e)
    for (int a = 0; a < npe; ++a)
      for (int b = 0; b < npe; ++b) neighbors[conn(e, a)].push_back(conn(e, b));
  FluidMatrixGraph g;
  g.num_rows = fluid_unknowns_per_node * nodes;
  g.node_offsets = Kokkos::View<int*>("rouleau::FluidMatrixGraph::node_offsets", nodes + 1);
  auto offsets = Kokkos::create_mirror_view(g.node_offsets);
  offsets(0) = 0;
  for (int n = 0; n < nodes; ++n) {
    auto& list = neighbors[n];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    offsets(n + 1) = offsets(n) + static_cast<int>(list.size());
  }
  g.node_neighbors = Kokkos::View<int*>("rouleau::FluidMatrixGraph::node_neighbors", offsets(nodes));
  auto node_neighbors = Kokkos::create_mirror_view(g.node_neighbors);
  g.row_map = Kokkos::View<std::size_t*>("rouleau::FluidMatrixGraph::row_map", g.num_rows + 1);
  auto row_map = Kokkos::create_mirror_view(g.row_map);
  row_map(0) = 0;
  for (int n = 0; n < nodes; ++n) {
    for (int k = offsets(n); k < offsets(n + 1); ++k) node_neighbors(k) = neighbors[n][k - offsets(n)];
    for (int i = 0; i < 4; ++i) row_map(4 * n + i + 1) = row_map(4 * n + i) + 4 * neighbors[n].size();
  }
  g.entries = Kokkos::View<int*>("rouleau::FluidMatrixGraph::entries", row_map(g.num_rows));
  auto entries = Kokkos::create_mirror_view(g.entries);
  for (int n = 0; n < nodes; ++n)
    for (int i = 0; i < 4; ++i) {
      std::size_t position = row_map(4 * n + i);
      for (int b : neighbors[n])
        for (int j = 0; j < 4; ++j) entries(position++) = 4 * b + j;
    }
  Kokkos::deep_copy(g.node_offsets, offsets);
  Kokkos::deep_copy(g.node_neighbors, node_neighbors);
  Kokkos::deep_copy(g.row_map, row_map);
  Kokkos::deep_copy(g.entries, entries);
  return g;
}

}  // namespace rouleau
