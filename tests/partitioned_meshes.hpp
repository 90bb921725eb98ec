#pragma once
// The meshes the MPI layer's tests partition: the shear box of the paper's
// scenes, small and graded in y, periodic in x and z (block partition), and its
// tetrahedra (a METIS partition: the path of Gmsh vessels) when the build has METIS.
#include <vector>

#include "mesh/fluid_mesh.hpp"
#include "parallel/element_partition.hpp"

namespace rouleau::testing {

inline FluidMesh shear_box() {
  return make_box_mesh({0, -5, 0}, {12, 5, 6}, {8, 4, 6}, {1.0, 1.3, 1.0}, {true, false, true});
}

inline std::vector<FluidMesh> partitioned_meshes() {
  std::vector<FluidMesh> meshes{shear_box()};
  if (has_graph_partitioner()) meshes.push_back(split_into_tetrahedra(meshes[0]));
  return meshes;
}

inline const char* partition_name(const FluidMesh& mesh) {
  return mesh.element_type == FluidElementType::hexahedron8 ? "box of hexahedra (blocks)" : "tetrahedra (METIS)";
}

}  // namespace rouleau::testing
