// The fluid mesh of a vessel: the Gmsh lumen's tetrahedra, its boundary named inlet,
// outlet and wall for the boundary conditions.
#include <algorithm>
#include <cmath>

#include "mesh/fluid_mesh.hpp"

namespace rouleau {

FluidMesh make_vessel_fluid_mesh(const VesselMesh& vessel, const VesselProfile& profile) {
  FluidMesh mesh;
  mesh.element_type = FluidElementType::tetrahedron4;
  mesh.nodes_per_element = 4;
  mesh.num_nodes = mesh.num_dof_nodes = static_cast<int>(vessel.nodes.size());
  mesh.num_elements = static_cast<int>(vessel.tetrahedra.size());
  mesh.coordinates = Kokkos::View<double* [3]>("rouleau::FluidMesh::coordinates", mesh.num_nodes);
  mesh.element_nodes = Kokkos::View<int**>("rouleau::FluidMesh::element_nodes", mesh.num_elements, 4);
  auto coordinates = Kokkos::create_mirror_view(mesh.coordinates);
  auto element_nodes = Kokkos::create_mirror_view(mesh.element_nodes);
  mesh.lower = {INFINITY, INFINITY, INFINITY};
  mesh.upper = {-INFINITY, -INFINITY, -INFINITY};
  for (int n = 0; n < mesh.num_nodes; ++n)
    for (int d = 0; d < 3; ++d) {
      coordinates(n, d) = vessel.nodes[n][d];
      mesh.lower[d] = std::min(mesh.lower[d], vessel.nodes[n][d]);
      mesh.upper[d] = std::max(mesh.upper[d], vessel.nodes[n][d]);
    }
  for (int e = 0; e < mesh.num_elements; ++e)
    for (int a = 0; a < 4; ++a) element_nodes(e, a) = vessel.tetrahedra[e][a];
  Kokkos::deep_copy(mesh.coordinates, coordinates);
  Kokkos::deep_copy(mesh.element_nodes, element_nodes);
  mesh.element_dof_nodes = mesh.element_nodes;  // no periodic sides: every node carries unknowns
  mesh.dof_node_of_node.resize(mesh.num_nodes);
  for (int n = 0; n < mesh.num_nodes; ++n) mesh.dof_node_of_node[n] = n;

  const double length = vessel_length(profile);
  const auto add_boundary = [&](const char* name, const std::vector<Triangle>& triangles, double normal_x,
                                double center_x) {
    BoundaryFaces b;
    b.name = name;
    for (const Triangle& f : triangles) {
      b.faces.push_back({f[0], f[1], f[2], f[2]});
      b.nodes.insert(b.nodes.end(), f.begin(), f.end());
    }
    std::sort(b.nodes.begin(), b.nodes.end());
    b.nodes.erase(std::unique(b.nodes.begin(), b.nodes.end()), b.nodes.end());
    if (normal_x != 0.0) {
      b.outward_normal = {normal_x, 0.0, 0.0};
      b.disc_center = {center_x, 0.0, 0.0};
      b.disc_radius = profile.radius;
    }
    mesh.boundaries.push_back(std::move(b));
  };
  add_boundary("inlet", vessel.inlet, -1.0, 0.0);
  add_boundary("outlet", vessel.outlet, 1.0, length);
  add_boundary("wall", vessel.wall, 0.0, 0.0);
  return mesh;
}

}  // namespace rouleau
