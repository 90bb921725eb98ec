#include "solver/block_jacobi_smoother.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "solver/matrix_values_read.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
using IntView = Kokkos::View<int*>;
using DoubleView = Kokkos::View<double*>;
using ConstView = Kokkos::View<const double*>;
using RoundedView = Kokkos::View<const float*>;

// blocks(16 A + 4i + j) = A's entry (4A + i, 4A + j): the diagonal block of each node
// (BlockMatrixGraph's layout: block of neighbour index n of row node A at
// 16 offsets(A) + 4 deg(A) i + 4 (n − offsets(A)) + j).
template <class Values>
void gather_diagonal_blocks(const BlockMatrixGraph& graph, const Values& values, const DoubleView& blocks) {
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

// next = z + ω D⁻¹ (r − A z), node by node (z empty: the first sweep from z = 0; r empty:
// r = 0, for the power iteration).
template <class Values>
void sweep(const BlockMatrixGraph& graph, const Values& values, const DoubleView& inverse, const double damping,
           const ConstView& r, const ConstView& z, const DoubleView& next) {
  const IntView offsets = graph.node_offsets, neighbors = graph.node_neighbors;
  const bool from_zero = z.extent(0) == 0, no_rhs = r.extent(0) == 0;
  Kokkos::parallel_for(
      "rouleau::BlockJacobiSmoother::sweep", Kokkos::RangePolicy<ExecSpace>(0, graph.num_rows / 4),
      KOKKOS_LAMBDA(const int A) {
        double residual[4];
        node_block_residual(offsets, neighbors, values, r, no_rhs, z, from_zero, A, residual);
        for (int i = 0; i < 4; ++i) {
          double update = 0.0;
          for (int j = 0; j < 4; ++j) update += inverse(16 * A + 4 * i + j) * residual[j];
          next(4 * A + i) = (from_zero ? 0.0 : z(4 * A + i)) + damping * update;
        }
      });
}

// ρ(D⁻¹A) by power iteration: x_0 a fixed vector of entries in [1/2, 3/2],
//   x_{k+1} = D⁻¹A x_k / |D⁻¹A x_k|,   ρ ≈ |D⁻¹A x_k| (|x_k| = 1),
// with D⁻¹A x = x − y for the sweep y = x + D⁻¹(0 − A x) (ω = 1, r = 0).
template <class Values>
double estimate_spectral_radius(const BlockMatrixGraph& graph, const Values& values, const DoubleView& inverse,
                                const DoubleView& x, const DoubleView& y, const int iterations) {
  const int n = graph.num_rows;
  Kokkos::parallel_for(
      "rouleau::BlockJacobiSmoother::power_start", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i) {
        const unsigned hash = (static_cast<unsigned>(i) + 1u) * 2654435761u;
        x(i) = 0.5 + static_cast<double>(hash >> 16) / 65536.0;
      });
  double squared = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::BlockJacobiSmoother::power_norm", Kokkos::RangePolicy<ExecSpace>(0, n),
      KOKKOS_LAMBDA(const int i, double& sum) { sum += x(i) * x(i); }, squared);
  double radius = 0.0;
  for (int k = 0; k < iterations && squared > 0.0; ++k) {
    const double scale = 1.0 / std::sqrt(squared);
    Kokkos::parallel_for(
        "rouleau::BlockJacobiSmoother::power_scale", Kokkos::RangePolicy<ExecSpace>(0, n),
        KOKKOS_LAMBDA(const int i) { x(i) *= scale; });
    sweep(graph, values, inverse, 1.0, ConstView(), x, y);
    // x ← D⁻¹A x = x − y, and its squared norm.
    Kokkos::parallel_reduce(
        "rouleau::BlockJacobiSmoother::power_step", Kokkos::RangePolicy<ExecSpace>(0, n),
        KOKKOS_LAMBDA(const int i, double& sum) {
          x(i) -= y(i);
          sum += x(i) * x(i);
        },
        squared);
    radius = std::sqrt(squared);
  }
  return radius;
}
}  // namespace

BlockJacobiSmoother::BlockJacobiSmoother(const BlockMatrixGraph& graph, const int sweeps,
                                         const double damping_times_radius)
    : graph_(graph),
      sweeps_(sweeps),
      damping_times_radius_(damping_times_radius),
      diagonal_blocks_("rouleau::BlockJacobiSmoother::diagonal_blocks", 4 * static_cast<std::size_t>(graph.num_rows)),
      other_("rouleau::BlockJacobiSmoother::other", graph.num_rows),
      power_vector_("rouleau::BlockJacobiSmoother::power_vector", graph.num_rows),
      inverse_(graph.num_rows / 4) {
  if (sweeps < 1 || !(damping_times_radius > 0.0 && damping_times_radius < 2.0))
    throw std::invalid_argument(
        "rouleau::BlockJacobiSmoother: sweeps must be >= 1 and the damping times the spectral radius in (0, 2), got " +
        std::to_string(sweeps) + " and " + std::to_string(damping_times_radius));
}

void BlockJacobiSmoother::factor(const Kokkos::View<double*>& values) { factor(values, RoundedView()); }

void BlockJacobiSmoother::factor(const Kokkos::View<double*>& values, const Kokkos::View<const float*>& rounded_values) {
  const bool rounded = rounded_values.extent(0) > 0;
  values_ = rounded ? ConstView() : ConstView(values);
  rounded_values_ = rounded_values;
  with_values_read(values_, rounded_values_, [&](const auto& swept) {
    gather_diagonal_blocks(graph_, swept, diagonal_blocks_);
    inverse_.factor(diagonal_blocks_);
    spectral_radius_ =
        estimate_spectral_radius(graph_, swept, inverse_.inverse_blocks(), power_vector_, other_, power_iterations);
  });
  damping_ = spectral_radius_ > 0.0 ? damping_times_radius_ / spectral_radius_ : 1.0;
}

void BlockJacobiSmoother::apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const {
  ProfilingRegion region("rouleau::BlockJacobiSmoother::apply");
  // The sweeps alternate between z and other_, the last one landing in z.
  DoubleView write = sweeps_ % 2 == 1 ? z : other_, read = sweeps_ % 2 == 1 ? other_ : z;
  with_values_read(values_, rounded_values_, [&](const auto& swept) {
    sweep(graph_, swept, inverse_.inverse_blocks(), damping_, r, ConstView(), write);
    for (int s = 1; s < sweeps_; ++s) {
      std::swap(read, write);
      sweep(graph_, swept, inverse_.inverse_blocks(), damping_, r, read, write);
    }
  });
}

}  // namespace rouleau
