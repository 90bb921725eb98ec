#pragma once
// A rank's part of the fluid mesh: the elements it owns as a FluidMesh of their
// own, on which every element kernel (FluidOperator) runs unchanged; the shared nodes'
// sums then meet through a NodeHalo.
#include "mesh/fluid_mesh.hpp"
#include "parallel/element_partition.hpp"

namespace rouleau {

// The partition of `mesh` for `rank` of `ranks`: the block partition of a structured box
// (block_element_owners), a METIS partition of any other mesh (graph_element_owners:
// Gmsh vessels, tetrahedra).
ElementPartition partition_fluid_mesh(const FluidMesh& mesh, int rank, int ranks);

// The rank's elements as a mesh: dof nodes numbered as in `partition` (owned first, then
// copies), geometric nodes those of its elements in ascending global order, the boundary
// faces of its elements (each face on exactly one rank; a side's `nodes` list every node of
// the side the rank holds). Periodic identification is carried by the dof numbering;
// `periodic` and `structured_elements` are cleared (the element path runs; the uniform-box
// stencil needs the whole box), `lower`/`upper` stay the global box.
FluidMesh make_local_mesh(const FluidMesh& mesh, const ElementPartition& partition);

}  // namespace rouleau
