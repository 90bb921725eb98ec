#pragma once
// The graph of the assembled fluid Jacobian (4×4 blocks of the mesh's node couplings) and
// the nodes' coupling strengths, for the preconditioners (the operator GMRES applies stays
// matrix-free).
#include <Kokkos_Core.hpp>
#include <cstddef>
#include <vector>

#include "mesh/fluid_mesh.hpp"
#include "solver/block_matrix_graph.hpp"
#include "host_algebra/pairwise_aggregation.hpp"

static_assert(rouleau::matrix_block_size == rouleau::fluid_unknowns_per_node, "the Jacobian's blocks are one node's unknowns");

namespace rouleau {

// The graph of the mesh's element couplings (built once: the mesh never moves).
BlockMatrixGraph build_fluid_matrix_graph(const FluidMesh& mesh);

// The strength graph for aggregation: weight 1/|x_a − x_b|² for every pair of dof nodes
// that share an element, the distance taken within the element (so a periodic boundary
// joins the nodes across it), the largest over the elements they share.
WeightedGraph fluid_node_strength(const FluidMesh& mesh);

}  // namespace rouleau
