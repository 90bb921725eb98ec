#include "solver/block_jacobi_smoother.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
using IntView = Kokkos::View<int*>;
using DoubleView = Kokkos::View<double*>;
using ConstView = Kokkos::View<const double*>;

// blocks(16 A + 4i + j) = A's entry (4A + i, 4A + j): the diagonal block of each node
// (BlockMatrixGraph's layout: block of neighbour index n of row node A at
// 16 offsets(A) + 4 deg(A) i + 4 (n − offsets(A)) + j).
void gather_diagonal_blocks(const BlockMatrixGraph& graph, const DoubleView& values, const DoubleView& blocks) {
  const IntView offsets = graph.node_offsets, neighbors = graph.node_neighbors;
  Kokkos::parallel_for(
      "rouleau::BlockJacobiSmoother::diagonal_blocks", Kokkos::RangePolicy<ExecSpace>(0, offsets.extent(0) - 1),
      KOKKOS_LAMBDA(const int A) {
        const int first = offsets(A), degree = offsets(A + 1) - first;
        int self = first;
        while (self < first + degree && neighbors(self) != A) ++self;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j)
            blocks(16 * A + 4 * i + j) =
                self < first + degree ? values(16 * std::size_t(first) + 4 * std::size_t(degree) * i +
                                               4 * (self - first) + j)
                                      : 0.0;
      });
}

// next = z + ω D⁻¹ (r − A z), node by node (z empty: the first sweep from z = 0).
void sweep(const BlockMatrixGraph& graph, const DoubleView& values, const DoubleView& inverse, const double damping,
           const ConstView& r, const ConstView& z, const DoubleView& next) {
  const auto row_map = graph.row_map;
  const auto entries = graph.entries;
  const bool from_zero = z.extent(0) == 0;
  Kokkos::parallel_for(
      "rouleau::BlockJacobiSmoother::sweep", Kokkos::RangePolicy<ExecSpace>(0, graph.num_rows / 4),
      KOKKOS_LAMBDA(const int A) {
        double residual[4];
        for (int i = 0; i < 4; ++i) {
          const int row = 4 * A + i;
          double sum = r(row);
          if (!from_zero)
            for (std::size_t k = row_map(row); k < row_map(row + 1); ++k) sum -= values(k) * z(entries(k));
          residual[i] = sum;
        }
        for (int i = 0; i < 4; ++i) {
          double update = 0.0;
          for (int j = 0; j < 4; ++j) update += inverse(16 * A + 4 * i + j) * residual[j];
          next(4 * A + i) = (from_zero ? 0.0 : z(4 * A + i)) + damping * update;
        }
      });
}
}  // namespace

BlockJacobiSmoother::BlockJacobiSmoother(const BlockMatrixGraph& graph, const int sweeps, const double damping)
    : graph_(graph),
      sweeps_(sweeps),
      damping_(damping),
      diagonal_blocks_("rouleau::BlockJacobiSmoother::diagonal_blocks", 4 * static_cast<std::size_t>(graph.num_rows)),
      other_("rouleau::BlockJacobiSmoother::other", sweeps > 1 ? graph.num_rows : 0),
      inverse_(graph.num_rows / 4) {
  if (sweeps < 1 || !(damping > 0.0))
    throw std::invalid_argument("rouleau::BlockJacobiSmoother: sweeps must be >= 1 and damping > 0, got " +
                                std::to_string(sweeps) + " and " + std::to_string(damping));
}

void BlockJacobiSmoother::factor(const Kokkos::View<double*>& values) {
  values_ = values;
  gather_diagonal_blocks(graph_, values_, diagonal_blocks_);
  inverse_.factor(diagonal_blocks_);
}

void BlockJacobiSmoother::apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const {
  ProfilingRegion region("rouleau::BlockJacobiSmoother::apply");
  // The sweeps alternate between z and other_, the last one landing in z.
  DoubleView write = sweeps_ % 2 == 1 ? z : other_, read = sweeps_ % 2 == 1 ? other_ : z;
  sweep(graph_, values_, inverse_.inverse_blocks(), damping_, r, ConstView(), write);
  for (int s = 1; s < sweeps_; ++s) {
    std::swap(read, write);
    sweep(graph_, values_, inverse_.inverse_blocks(), damping_, r, read, write);
  }
}

}  // namespace rouleau
