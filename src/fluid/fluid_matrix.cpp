#include "fluid/fluid_matrix.hpp"

#include <algorithm>
#include <map>
#include <vector>

namespace rouleau {

void flatten_node_lists(std::vector<std::vector<int>>& lists, std::vector<int>& offsets, std::vector<int>& neighbors) {
  offsets.assign(lists.size() + 1, 0);
  neighbors.clear();
  for (std::size_t n = 0; n < lists.size(); ++n) {
    auto& list = lists[n];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    offsets[n + 1] = offsets[n] + static_cast<int>(list.size());
    neighbors.insert(neighbors.end(), list.begin(), list.end());
  }
}

FluidMatrixGraph make_block_matrix_graph(const std::vector<int>& node_offsets, const std::vector<int>& node_neighbors) {
  const int nodes = static_cast<int>(node_offsets.size()) - 1;
  FluidMatrixGraph g;
  g.num_rows = fluid_unknowns_per_node * nodes;
  g.node_offsets = Kokkos::View<int*>("rouleau::FluidMatrixGraph::node_offsets", nodes + 1);
  g.node_neighbors = Kokkos::View<int*>("rouleau::FluidMatrixGraph::node_neighbors", node_offsets[nodes]);
  g.row_map = Kokkos::View<std::size_t*>("rouleau::FluidMatrixGraph::row_map", g.num_rows + 1);
  g.entries = Kokkos::View<int*>("rouleau::FluidMatrixGraph::entries", 16 * static_cast<std::size_t>(node_offsets[nodes]));
  auto offsets = Kokkos::create_mirror_view(g.node_offsets);
  auto neighbors = Kokkos::create_mirror_view(g.node_neighbors);
  auto row_map = Kokkos::create_mirror_view(g.row_map);
  auto entries = Kokkos::create_mirror_view(g.entries);
  for (int n = 0; n <= nodes; ++n) offsets(n) = node_offsets[n];
  for (int k = 0; k < node_offsets[nodes]; ++k) neighbors(k) = node_neighbors[k];
  row_map(0) = 0;
  for (int n = 0; n < nodes; ++n) {
    const int degree = node_offsets[n + 1] - node_offsets[n];
    for (int i = 0; i < 4; ++i) {
      std::size_t position = row_map(4 * n + i);
      for (int k = node_offsets[n]; k < node_offsets[n + 1]; ++k)
        for (int j = 0; j < 4; ++j) entries(position++) = 4 * node_neighbors[k] + j;
      row_map(4 * n + i + 1) = row_map(4 * n + i) + 4 * static_cast<std::size_t>(degree);
    }
  }
  Kokkos::deep_copy(g.node_offsets, offsets);
  Kokkos::deep_copy(g.node_neighbors, neighbors);
  Kokkos::deep_copy(g.row_map, row_map);
  Kokkos::deep_copy(g.entries, entries);
  return g;
}

FluidMatrixGraph build_fluid_matrix_graph(const FluidMesh& mesh) {
  auto conn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_dof_nodes);
  const int nodes = mesh.num_dof_nodes, npe = mesh.nodes_per_element;
  std::vector<std::vector<int>> neighbors(nodes);
  for (int e = 0; e < mesh.num_elements; ++e)
    for (int a = 0; a < npe; ++a)
      for (int b = 0; b < npe; ++b) neighbors[conn(e, a)].push_back(conn(e, b));
  std::vector<int> offsets, flat;
  flatten_node_lists(neighbors, offsets, flat);
  return make_block_matrix_graph(offsets, flat);
}

WeightedGraph fluid_node_strength(const FluidMesh& mesh) {
  auto dof_nodes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_dof_nodes);
  auto geometric = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_nodes);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const int npe = mesh.nodes_per_element;
  std::vector<std::map<int, double>> strongest(mesh.num_dof_nodes);
  for (int e = 0; e < mesh.num_elements; ++e)
    for (int a = 0; a < npe; ++a)
      for (int b = 0; b < npe; ++b) {
        const int A = dof_nodes(e, a), B = dof_nodes(e, b);
        if (A == B) continue;
        double distance_squared = 0.0;
        for (int d = 0; d < 3; ++d) {
          const double dx = x(geometric(e, a), d) - x(geometric(e, b), d);
          distance_squared += dx * dx;
        }
        double& weight = strongest[A][B];
        weight = std::max(weight, 1.0 / distance_squared);
      }
  WeightedGraph graph;
  graph.offsets.assign(mesh.num_dof_nodes + 1, 0);
  for (int A = 0; A < mesh.num_dof_nodes; ++A) {
    for (const auto& [B, weight] : strongest[A]) {
      graph.neighbors.push_back(B);
      graph.weights.push_back(weight);
    }
    graph.offsets[A + 1] = static_cast<int>(graph.neighbors.size());
  }
  return graph;
}

}  // namespace rouleau
