#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mesh/fluid_mesh.hpp"

namespace rouleau {

const BoundaryFaces& FluidMesh::boundary(const std::string& name) const {
  for (const auto& b : boundaries)
    if (b.name == name) return b;
  throw std::out_of_range("rouleau::FluidMesh::boundary: no boundary named '" + name + "'");
}

FluidMesh make_box_mesh(const std::array<double, 3>& lower, const std::array<double, 3>& upper,
                        const std::array<int, 3>& elements, const std::array<double, 3>& grading,
                        const std::array<bool, 3>& periodic) {
  FluidMesh mesh;
  mesh.element_type = FluidElementType::hexahedron8;
  mesh.nodes_per_element = 8;
  mesh.lower = lower;
  mesh.upper = upper;
  mesh.periodic = periodic;
  mesh.structured_elements = elements;
  const int nx = elements[0], ny = elements[1], nz = elements[2];
  const int px = nx + 1, py = ny + 1, pz = nz + 1;  // geometric node planes
  std::array<std::vector<double>, 3> axis;
  for (int d = 0; d < 3; ++d) axis[d] = graded_coordinates(lower[d], upper[d], elements[d], grading[d]);

  auto node_id = [&](int i, int j, int k) { return i + px * (j + py * k); };
  // Periodic directions wrap the last plane onto the first: dof planes count n instead of n+1.
  const int dx = periodic[0] ? nx : px, dy = periodic[1] ? ny : py, dz = periodic[2] ? nz : pz;
  auto dof_id = [&](int i, int j, int k) { return (i % dx) + dx * ((j % dy) + dy * (k % dz)); };

  mesh.num_nodes = px * py * pz;
  mesh.num_dof_nodes = dx * dy * dz;
  mesh.num_elements = nx * ny * nz;
  mesh.coordinates = Kokkos::View<double* [3]>("rouleau::FluidMesh::coordinates", mesh.num_nodes);
  mesh.element_nodes = Kokkos::View<int**>("rouleau::FluidMesh::element_nodes", mesh.num_elements, 8);
  mesh.element_dof_nodes = Kokkos::View<int**>("rouleau::FluidMesh::element_dof_nodes", mesh.num_elements, 8);
  auto coordinates = Kokkos::create_mirror_view(mesh.coordinates);
  auto element_nodes = Kokkos::create_mirror_view(mesh.element_nodes);
  auto element_dof_nodes = Kokkos::create_mirror_view(mesh.element_dof_nodes);
  mesh.dof_node_of_node.resize(mesh.num_nodes);

  for (int k = 0; k < pz; ++k)
    for (int j = 0; j < py; ++j)
      for (int i = 0; i < px; ++i) {
        const int n = node_id(i, j, k);
        coordinates(n, 0) = axis[0][i];
        coordinates(n, 1) = axis[1][j];
        coordinates(n, 2) = axis[2][k];
        mesh.dof_node_of_node[n] = dof_id(i, j, k);
      }
  // Hexahedron node order (VTK): bottom face counter-clockwise, then top face.
  constexpr int corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int e = i + nx * (j + ny * k);
        for (int a = 0; a < 8; ++a) {
          const int n = node_id(i + corner[a][0], j + corner[a][1], k + corner[a][2]);
          element_nodes(e, a) = n;
          element_dof_nodes(e, a) = mesh.dof_node_of_node[n];
        }
      }
  Kokkos::deep_copy(mesh.coordinates, coordinates);
  Kokkos::deep_copy(mesh.element_nodes, element_nodes);
  Kokkos::deep_copy(mesh.element_dof_nodes, element_dof_nodes);

  // Boundary sides: the faces on each of the six planes, oriented outward.
  const std::array<int, 3> plane_count{px, py, pz};
  for (int side = 0; side < 6; ++side) {
    const int d = side / 2;             // normal direction
    const bool at_max = side % 2 == 1;  // x_max, y_max, z_max
    const int t1 = (d + 1) % 3, t2 = (d + 2) % 3;
    BoundaryFaces b;
    b.name = std::string(1, "xyz"[d]) + (at_max ? "_max" : "_min");
    b.outward_normal[d] = at_max ? 1.0 : -1.0;
    const int fixed = at_max ? plane_count[d] - 1 : 0;
    auto id = [&](int a1, int a2) {
      int ijk[3];
      ijk[d] = fixed;
      ijk[t1] = a1;
      ijk[t2] = a2;
      return node_id(ijk[0], ijk[1], ijk[2]);
    };
    for (int a2 = 0; a2 < plane_count[t2]; ++a2)
      for (int a1 = 0; a1 < plane_count[t1]; ++a1) b.nodes.push_back(id(a1, a2));
    std::sort(b.nodes.begin(), b.nodes.end());
    for (int a2 = 0; a2 + 1 < plane_count[t2]; ++a2)
      for (int a1 = 0; a1 + 1 < plane_count[t1]; ++a1) {
        // (t1, t2, d) is right-handed, so this order has normal +d; flip it on the min side.
        std::array<int, 4> f{id(a1, a2), id(a1 + 1, a2), id(a1 + 1, a2 + 1), id(a1, a2 + 1)};
        if (!at_max) std::swap(f[1], f[3]);
        b.faces.push_back(f);
      }
    mesh.boundaries.push_back(std::move(b));
  }
  return mesh;
}

}  // namespace rouleau
