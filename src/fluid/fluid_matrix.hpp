#pragma once
// The assembled fluid Jacobian in CRS form, for preconditioners only (DESIGN.md: the
// operator GMRES applies stays matrix-free). Unknowns are node-interleaved, so the graph
// is the node graph with every node pair expanded into a 4×4 block.
#include <Kokkos_Core.hpp>
#include <cstddef>
#include <vector>

#include "mesh/fluid_mesh.hpp"
#include "host_algebra/pairwise_aggregation.hpp"

namespace rouleau {

struct FluidMatrixGraph {
  int num_rows = 0;
  Kokkos::View<std::size_t*> row_map;  // num_rows + 1
  Kokkos::View<int*> entries;          // columns, sorted within each row
  // The node graph: dof nodes coupled to node A (sorted, A included) are
  // node_neighbors(node_offsets(A) .. node_offsets(A+1)); row 4A+i holds, for the k-th
  // neighbor B, the columns 4B..4B+3 at row_map(4A+i) + 4k. So the entry (i, j) of the
  // block of neighbour index n = node_offsets(A) + k sits at
  // 16 node_offsets(A) + 4 deg(A) i + 4 k + j, deg(A) = node_offsets(A+1) − node_offsets(A).
  Kokkos::View<int*> node_offsets;
  Kokkos::View<int*> node_neighbors;
};

// The graph of the mesh's element couplings (built once: the mesh never moves).
FluidMatrixGraph build_fluid_matrix_graph(const FluidMesh& mesh);

// Sorts each node's neighbour list, drops repeats, and flattens the lists into CSR form.
void flatten_node_lists(std::vector<std::vector<int>>& lists, std::vector<int>& offsets, std::vector<int>& neighbors);

// The block graph of a node graph given on the host (each node's neighbours sorted, the
// node itself among them).
FluidMatrixGraph make_block_matrix_graph(const std::vector<int>& node_offsets, const std::vector<int>& node_neighbors);

// Rows `rows` of the matrix (values on `graph`) become the identity's rows: the Dirichlet
// rows of an assembled Jacobian. Runs on ExecSpace.
template <class ExecSpace = Kokkos::DefaultExecutionSpace>
void set_identity_rows(const FluidMatrixGraph& graph, const Kokkos::View<int*>& rows, const Kokkos::View<double*>& values) {
  auto row_map = graph.row_map;
  auto entries = graph.entries;
  Kokkos::parallel_for(
      "rouleau::set_identity_rows", Kokkos::RangePolicy<ExecSpace>(0, rows.extent(0)), KOKKOS_LAMBDA(const int k) {
        const int row = rows(k);
        for (std::size_t p = row_map(row); p < row_map(row + 1); ++p) values(p) = entries(p) == row ? 1.0 : 0.0;
      });
}

// The strength graph for aggregation: weight 1/|x_a − x_b|² for every pair of dof nodes
// that share an element, the distance taken within the element (so a periodic boundary
// joins the nodes across it), the largest over the elements they share.
WeightedGraph fluid_node_strength(const FluidMesh& mesh);

}  // namespace rouleau
