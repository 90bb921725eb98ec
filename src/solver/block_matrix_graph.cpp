#include "solver/block_matrix_graph.hpp"

#include <algorithm>
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

BlockMatrixGraph make_block_matrix_graph(const std::vector<int>& node_offsets, const std::vector<int>& node_neighbors) {
  const int nodes = static_cast<int>(node_offsets.size()) - 1;
  BlockMatrixGraph g;
  g.num_rows = matrix_block_size * nodes;
  g.node_offsets = Kokkos::View<int*>("rouleau::BlockMatrixGraph::node_offsets", nodes + 1);
  g.node_neighbors = Kokkos::View<int*>("rouleau::BlockMatrixGraph::node_neighbors", node_offsets[nodes]);
  g.row_map = Kokkos::View<std::size_t*>("rouleau::BlockMatrixGraph::row_map", g.num_rows + 1);
  g.entries = Kokkos::View<int*>("rouleau::BlockMatrixGraph::entries", 16 * static_cast<std::size_t>(node_offsets[nodes]));
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

}  // namespace rouleau
