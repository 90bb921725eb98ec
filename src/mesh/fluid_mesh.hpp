#pragma once
// The fixed Eulerian mesh of the fluid: coordinates, element connectivity, periodic
// identification of nodes and tagged boundary faces.
//
// Geometric nodes carry coordinates (output shows them all). Periodic sides identify
// nodes: `dof_node_of_node` maps a geometric node to the node that carries its unknowns,
// and `element_dof_nodes` is the connectivity in those. Unknowns are node-interleaved:
// index 4·dof_node + c with c = 0,1,2 the velocity components and c = 3 the pressure.
#include <Kokkos_Core.hpp>
#include <array>
#include <string>
#include <vector>

#include "geometry/grading.hpp"
#include "geometry/vessel_mesh.hpp"

namespace rouleau {

enum class FluidElementType { hexahedron8, tetrahedron4 };

inline constexpr int fluid_unknowns_per_node = 4;

struct BoundaryFaces {
  std::string name;                             // "x_min", ... (or a Gmsh physical name)
  std::vector<std::array<int, 4>> faces;        // geometric nodes of each face (quads; tets repeat the last)
  std::vector<int> nodes;                       // geometric nodes on this boundary, sorted, unique
  std::array<double, 3> outward_normal{0, 0, 0};  // for planar sides; zero for curved ones
  // A planar circular side (a vessel's inlet or outlet): its centre [μm] and radius [μm];
  // radius 0 for any other side.
  std::array<double, 3> disc_center{0, 0, 0};
  double disc_radius = 0.0;
};

struct FluidMesh {
  FluidElementType element_type = FluidElementType::hexahedron8;
  int nodes_per_element = 8;
  int num_nodes = 0;       // geometric nodes
  int num_dof_nodes = 0;   // nodes carrying unknowns (after periodic identification)
  int num_elements = 0;

  Kokkos::View<double* [3]> coordinates;        // [num_nodes][3], μm
  Kokkos::View<int**> element_nodes;            // [num_elements][nodes_per_element], geometric
  Kokkos::View<int**> element_dof_nodes;        // same, in dof nodes
  std::vector<int> dof_node_of_node;            // host: geometric → dof node
  std::vector<BoundaryFaces> boundaries;        // host

  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0};  // bounding box, μm
  std::array<bool, 3> periodic{false, false, false};
  // A structured box of hexahedra (make_box_mesh): elements per direction, element
  // (i, j, k) at index i + n_x (j + n_y k) and dof node (i, j, k) at i + d_x (j + d_y k),
  // d = n in periodic directions and n + 1 otherwise. {0, 0, 0} for any other mesh.
  std::array<int, 3> structured_elements{0, 0, 0};

  int num_unknowns() const { return fluid_unknowns_per_node * num_dof_nodes; }
  const BoundaryFaces& boundary(const std::string& name) const;
};

// A structured box of 8-node hexahedra; directions flagged periodic identify their
// first and last planes of nodes. Sides are named x_min, x_max, y_min, y_max, z_min, z_max.
FluidMesh make_box_mesh(const std::array<double, 3>& lower, const std::array<double, 3>& upper,
                        const std::array<int, 3>& elements, const std::array<double, 3>& grading,
                        const std::array<bool, 3>& periodic);

// The same nodes with every hexahedron cut into six tetrahedra (Kuhn's subdivision around
// its diagonal from node 0 to node 6, conforming between neighbours); boundary
// quadrilaterals become two triangles. For tests and benchmarks of the tetrahedral
// element against the hexahedral one on one set of unknowns.
FluidMesh split_into_tetrahedra(const FluidMesh& hexahedra);

// The fluid mesh of a vessel's lumen (its axis along x): boundaries "inlet" (the disc at
// x = 0, outward normal −x), "outlet" (the disc at x = L, +x) and "wall" (curved: no normal).
FluidMesh make_vessel_fluid_mesh(const VesselMesh& vessel, const VesselProfile& profile);

}  // namespace rouleau
