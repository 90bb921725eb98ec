#include "distributed/local_mesh.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace rouleau {

ElementPartition partition_fluid_mesh(const FluidMesh& mesh, int rank, int ranks) {
  auto connectivity = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_dof_nodes);
  std::vector<int> element_dof_nodes(static_cast<std::size_t>(mesh.num_elements) * mesh.nodes_per_element);
  for (int e = 0; e < mesh.num_elements; ++e)
    for (int a = 0; a < mesh.nodes_per_element; ++a) element_dof_nodes[e * mesh.nodes_per_element + a] = connectivity(e, a);
  const auto& n = mesh.structured_elements;
  const bool structured = n[0] * n[1] * n[2] == mesh.num_elements && mesh.num_elements > 0;
  const int face_nodes = mesh.element_type == FluidElementType::hexahedron8 ? 4 : 3;
  const std::vector<int> owners =
      structured ? block_element_owners(n, ranks)
                 : graph_element_owners(element_dof_nodes, mesh.nodes_per_element, mesh.num_dof_nodes, face_nodes, ranks);
  return make_element_partition(rank, ranks, owners, element_dof_nodes, mesh.nodes_per_element, mesh.num_dof_nodes);
}

FluidMesh make_local_mesh(const FluidMesh& mesh, const ElementPartition& partition) {
  const int npe = mesh.nodes_per_element;
  auto nodes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_nodes);
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);

  // global dof node → local; global geometric node → local (those of the rank's elements)
  std::vector<int> local_dof(mesh.num_dof_nodes, -1), local_geometric(mesh.num_nodes, -1);
  for (int l = 0; l < partition.num_local_nodes(); ++l) local_dof[partition.global_node[l]] = l;
  std::vector<char> held(mesh.num_nodes, 0);
  for (const int e : partition.elements)
    for (int a = 0; a < npe; ++a) held[nodes(e, a)] = 1;
  std::vector<int> geometric;  // local geometric node → global
  for (int g = 0; g < mesh.num_nodes; ++g)
    if (held[g]) local_geometric[g] = static_cast<int>(geometric.size()), geometric.push_back(g);

  FluidMesh local;
  local.element_type = mesh.element_type;
  local.nodes_per_element = npe;
  local.num_nodes = static_cast<int>(geometric.size());
  local.num_dof_nodes = partition.num_local_nodes();
  local.num_elements = static_cast<int>(partition.elements.size());
  local.lower = mesh.lower;
  local.upper = mesh.upper;

  local.coordinates = Kokkos::View<double* [3]>("rouleau::LocalMesh::coordinates", local.num_nodes);
  local.element_nodes = Kokkos::View<int**>("rouleau::LocalMesh::element_nodes", local.num_elements, npe);
  local.element_dof_nodes = Kokkos::View<int**>("rouleau::LocalMesh::element_dof_nodes", local.num_elements, npe);
  auto x = Kokkos::create_mirror_view(local.coordinates);
  auto element_nodes = Kokkos::create_mirror_view(local.element_nodes);
  auto element_dof_nodes = Kokkos::create_mirror_view(local.element_dof_nodes);
  local.dof_node_of_node.resize(local.num_nodes);
  for (int l = 0; l < local.num_nodes; ++l) {
    const int g = geometric[l];
    for (int d = 0; d < 3; ++d) x(l, d) = coordinates(g, d);
    local.dof_node_of_node[l] = local_dof[mesh.dof_node_of_node[g]];
  }
  for (int e = 0; e < local.num_elements; ++e)
    for (int a = 0; a < npe; ++a) {
      const int g = nodes(partition.elements[e], a);
      element_nodes(e, a) = local_geometric[g];
      element_dof_nodes(e, a) = local_dof[mesh.dof_node_of_node[g]];
    }
  Kokkos::deep_copy(local.coordinates, x);
  Kokkos::deep_copy(local.element_nodes, element_nodes);
  Kokkos::deep_copy(local.element_dof_nodes, element_dof_nodes);

  // A boundary face belongs to the one element that holds all its nodes: the rank keeps
  // the faces of its own elements (a face whose nodes are all shared may lie on another
  // rank's element; counted twice, it would double a traction load or a flux).
  std::vector<std::vector<int>> elements_at(mesh.num_nodes);  // geometric node → the rank's elements
  for (const int e : partition.elements)
    for (int a = 0; a < npe; ++a) elements_at[nodes(e, a)].push_back(e);
  const auto of_own_element = [&](const std::array<int, 4>& face) {
    for (const int e : elements_at[face[0]]) {
      bool holds_all = true;
      for (const int g : face) {
        bool in_element = false;
        for (int a = 0; a < npe; ++a) in_element = in_element || nodes(e, a) == g;
        holds_all = holds_all && in_element;
      }
      if (holds_all) return true;
    }
    return false;
  };
  for (const BoundaryFaces& side : mesh.boundaries) {
    BoundaryFaces part = side;
    part.faces.clear();
    part.nodes.clear();
    for (const auto& face : side.faces) {
      if (!held[face[0]] || !of_own_element(face)) continue;
      part.faces.push_back({local_geometric[face[0]], local_geometric[face[1]], local_geometric[face[2]],
                            local_geometric[face[3]]});
    }
    for (const int g : side.nodes)
      if (local_geometric[g] >= 0) part.nodes.push_back(local_geometric[g]);
    std::sort(part.nodes.begin(), part.nodes.end());
    local.boundaries.push_back(std::move(part));
  }
  return local;
}

}  // namespace rouleau
