#pragma once
// The graph of a sparse matrix of 4×4 blocks in CRS form, for preconditioners (the
// operator GMRES applies stays matrix-free). Unknowns are node-interleaved (4 per node), so
// the graph is a node graph with every node pair expanded into a 4×4 block.
#include <Kokkos_Core.hpp>
#include <cstddef>
#include <vector>

namespace rouleau {

inline constexpr int matrix_block_size = 4;

struct BlockMatrixGraph {
  int num_rows = 0;
  Kokkos::View<std::size_t*> row_map;  // num_rows + 1
  Kokkos::View<int*> entries;          // columns, sorted within each row
  // The node graph: nodes coupled to node A (sorted, A included) are
  // node_neighbors(node_offsets(A) .. node_offsets(A+1)); row 4A+i holds, for the k-th
  // neighbor B, the columns 4B..4B+3 at row_map(4A+i) + 4k. So the entry (i, j) of the
  // block of neighbour index n = node_offsets(A) + k sits at
  // 16 node_offsets(A) + 4 deg(A) i + 4 k + j, deg(A) = node_offsets(A+1) − node_offsets(A).
  Kokkos::View<int*> node_offsets;
  Kokkos::View<int*> node_neighbors;
};

// Sorts each node's neighbour list, drops repeats, and flattens the lists into CSR form.
void flatten_node_lists(std::vector<std::vector<int>>& lists, std::vector<int>& offsets, std::vector<int>& neighbors);

// The block graph of a node graph given on the host (each node's neighbours sorted, the
// node itself among them).
BlockMatrixGraph make_block_matrix_graph(const std::vector<int>& node_offsets, const std::vector<int>& node_neighbors);

// Rows `rows` of the matrix (values on `graph`) become the identity's rows: the Dirichlet
// rows of an assembled Jacobian. Runs on ExecSpace.
template <class ExecSpace = Kokkos::DefaultExecutionSpace>
void set_identity_rows(const BlockMatrixGraph& graph, const Kokkos::View<int*>& rows, const Kokkos::View<double*>& values) {
  auto row_map = graph.row_map;
  auto entries = graph.entries;
  Kokkos::parallel_for(
      "rouleau::set_identity_rows", Kokkos::RangePolicy<ExecSpace>(0, rows.extent(0)), KOKKOS_LAMBDA(const int k) {
        const int row = rows(k);
        for (std::size_t p = row_map(row); p < row_map(row + 1); ++p) values(p) = entries(p) == row ? 1.0 : 0.0;
      });
}

}  // namespace rouleau
