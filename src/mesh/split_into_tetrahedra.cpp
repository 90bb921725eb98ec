// A hexahedral box mesh cut into tetrahedra (Kuhn's subdivision), for tetrahedral-element
// tests and benchmarks on the same nodes as the hexahedra.
#include <algorithm>
#include <stdexcept>

#include "mesh/fluid_mesh.hpp"

namespace rouleau {

FluidMesh split_into_tetrahedra(const FluidMesh& hexahedra) {
  if (hexahedra.element_type != FluidElementType::hexahedron8)
    throw std::invalid_argument("rouleau::split_into_tetrahedra: the mesh is not made of hexahedra");
  FluidMesh mesh = hexahedra;
  mesh.element_type = FluidElementType::tetrahedron4;
  mesh.structured_elements = {0, 0, 0};
  mesh.nodes_per_element = 4;
  mesh.num_elements = 6 * hexahedra.num_elements;
  // Corner offsets of the VTK hexahedron (see make_box_mesh) and the corner index of an offset.
  constexpr int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const auto corner_of = [&](const int offset[3]) {
    for (int a = 0; a < 8; ++a)
      if (corner[a][0] == offset[0] && corner[a][1] == offset[1] && corner[a][2] == offset[2]) return a;
    return -1;
  };
  // Kuhn: one tetrahedron per order (d1, d2, d3) of the axes, the path 0 → +e_d1 → +e_d2 →
  // +e_d3 from corner 0 to corner 6. Every hexahedron is cut the same way, so the cuts of
  // neighbours meet: each face is split along its diagonal from its lowest corner.
  int tetrahedra[6][4];
  int axes[3] = {0, 1, 2}, t = 0;
  do {
    int offset[3] = {0, 0, 0};
    tetrahedra[t][0] = corner_of(offset);
    for (int k = 0; k < 3; ++k) {
      offset[axes[k]] = 1;
      tetrahedra[t][k + 1] = corner_of(offset);
    }
    // Orientation: (x1 − x0)·((x2 − x0) × (x3 − x0)) has the sign of the order's parity.
    const int inversions = (axes[0] > axes[1]) + (axes[0] > axes[2]) + (axes[1] > axes[2]);
    const bool odd = inversions % 2 == 1;
    if (odd) std::swap(tetrahedra[t][2], tetrahedra[t][3]);
    ++t;
  } while (std::next_permutation(axes, axes + 3));

  mesh.element_nodes = Kokkos::View<int**>("rouleau::FluidMesh::element_nodes", mesh.num_elements, 4);
  mesh.element_dof_nodes = Kokkos::View<int**>("rouleau::FluidMesh::element_dof_nodes", mesh.num_elements, 4);
  auto hex_nodes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hexahedra.element_nodes);
  auto nodes = Kokkos::create_mirror_view(mesh.element_nodes);
  auto dof_nodes = Kokkos::create_mirror_view(mesh.element_dof_nodes);
  for (int e = 0; e < hexahedra.num_elements; ++e)
    for (int k = 0; k < 6; ++k)
      for (int a = 0; a < 4; ++a) {
        const int node = hex_nodes(e, tetrahedra[k][a]);
        nodes(6 * e + k, a) = node;
        dof_nodes(6 * e + k, a) = mesh.dof_node_of_node[node];
      }
  Kokkos::deep_copy(mesh.element_nodes, nodes);
  Kokkos::deep_copy(mesh.element_dof_nodes, dof_nodes);

  // Boundary quadrilaterals (f0, f1, f2, f3) split along f0–f2, their lowest-to-highest
  // diagonal as in the volume; triangles repeat their last node.
  for (auto& b : mesh.boundaries) {
    std::vector<std::array<int, 4>> triangles;
    for (const auto& f : b.faces) {
      triangles.push_back({f[0], f[1], f[2], f[2]});
      triangles.push_back({f[0], f[2], f[3], f[3]});
    }
    b.faces = std::move(triangles);
  }
  return mesh;
}

}  // namespace rouleau
