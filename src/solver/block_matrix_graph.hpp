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

// The four residuals of node A's rows, r_i = b(4A + i) − Σ_B Σ_j A_AB(i, j) x(4B + j), read
// block by block: one column index per 4×4 block and x_B loaded once for the four rows
// (a scalar CRS product reads an index per entry and x_B four times). With `zero_rhs`, b
// = 0; with `zero_x`, x = 0 (r = b, nothing read).
template <class Values, class Rhs, class Solution>
KOKKOS_INLINE_FUNCTION void node_block_residual(const Kokkos::View<int*>& node_offsets,
                                                const Kokkos::View<int*>& node_neighbors, const Values& values,
                                                const Rhs& b, const bool zero_rhs, const Solution& x,
                                                const bool zero_x, const int A, double residual[4]) {
  for (int i = 0; i < 4; ++i) residual[i] = zero_rhs ? 0.0 : b(4 * A + i);
  if (zero_x) return;
  const int first = node_offsets(A), degree = node_offsets(A + 1) - first;
  const std::size_t base = 16 * static_cast<std::size_t>(first), row_stride = 4 * static_cast<std::size_t>(degree);
  for (int k = 0; k < degree; ++k) {
    const int B = node_neighbors(first + k);
    const double x0 = x(4 * B), x1 = x(4 * B + 1), x2 = x(4 * B + 2), x3 = x(4 * B + 3);
    for (int i = 0; i < 4; ++i) {
      const std::size_t e = base + row_stride * i + 4 * k;
      residual[i] -= values(e) * x0 + values(e + 1) * x1 + values(e + 2) * x2 + values(e + 3) * x3;
    }
  }
}

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
