#include "fluid/fluid_matrix.hpp"

#include <algorithm>
#include <map>
#include <vector>

namespace rouleau {

BlockMatrixGraph build_fluid_matrix_graph(const FluidMesh& mesh) {
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
