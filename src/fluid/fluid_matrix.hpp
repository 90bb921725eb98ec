#pragma once
// The assembled fluid Jacobian in CRS form, for preconditioners only (DESIGN.md: the
// operator GMRES applies stays matrix-free). Unknowns are node-interleaved, so the graph
// is the node graph with every node pair expanded into a 4×4 block.
#include <Kokkos_Core.hpp>
#include <cstddef>

#include "mesh/fluid_mesh.hpp"

namespace rouleau {

struct FluidMatrixGraph {
  int num_rows = 0;
  Kokkos::View<std::size_t*> row_map;  // num_rows + 1
  Kokkos::View<int*> entries;          // columns, sorted within each row
  // The node graph: dof nodes coupled to node A (sorted, A included) are
  // node_neighbors(node_offsets(A) .. node_offsets(A+1)); row 4A+i holds, for the k-th
  // neighbor B, the columns 4B..4B+3 at row_map(4A+i) + 4k.
  Kokkos::View<int*> node_offsets;
  Kokkos::View<int*> node_neighbors;
};

// The graph of the mesh's element couplings (built once: the mesh never moves).
FluidMatrixGraph build_fluid_matrix_graph(const FluidMesh& mesh);

}  // namespace rouleau
