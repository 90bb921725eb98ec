#include "solver/aggregation_multigrid.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "util/profiling_region.hpp"
#include "util/view_transfer.hpp"
#include "solver/block_jacobi_smoother.hpp"
#include "solver/ilu0_preconditioner.hpp"
#include "solver/matrix_values_read.hpp"
#include "host_algebra/sparse_direct_solver.hpp"

namespace rouleau {

namespace {

using IntView = Kokkos::View<int*>;
using DoubleView = Kokkos::View<double*>;
using ConstView = Kokkos::View<const double*>;
using FloatView = Kokkos::View<float*>;

// Position of entry (i, j) of the block at neighbour index n of row node A
// (BlockMatrixGraph's layout).
KOKKOS_INLINE_FUNCTION std::size_t block_entry(const IntView& offsets, int A, int n, int i, int j) {
  const int first = offsets(A), degree = offsets(A + 1) - first;
  return 16 * static_cast<std::size_t>(first) + 4 * static_cast<std::size_t>(degree) * i + 4 * (n - first) + j;
}

}  // namespace

struct AggregationMultigrid::Level {
  BlockMatrixGraph graph;
  DoubleView values;
  FloatView rounded_values;  // the values rounded to float, when the sweeps read that
  IntView block_row;  // row node of each block (neighbour index)
  std::unique_ptr<MatrixPreconditioner> smoother;
  DoubleView rhs, solution, residual, correction;
  // Towards the next, coarser level (empty on the coarsest):
  IntView aggregate_of;                          // node -> coarse node
  IntView member_offsets, members;               // coarse node -> its nodes
  IntView contribution_offsets, contributions;   // coarse block -> the blocks summed into it
};

struct AggregationMultigrid::CoarsestSolver {
  std::unique_ptr<SparseDirectSolver> lu;
  Kokkos::View<double*>::HostMirror rhs, solution;
  std::vector<double> values;
};

namespace {

// Host copy of a level's node graph.
void host_node_graph(const BlockMatrixGraph& graph, std::vector<int>& offsets, std::vector<int>& neighbors) {
  auto o = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), graph.node_offsets);
  auto n = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), graph.node_neighbors);
  offsets.assign(o.data(), o.data() + o.extent(0));
  neighbors.assign(n.data(), n.data() + n.extent(0));
}

std::vector<int> block_rows(const std::vector<int>& offsets) {
  std::vector<int> rows(offsets.back());
  for (std::size_t A = 0; A + 1 < offsets.size(); ++A)
    for (int k = offsets[A]; k < offsets[A + 1]; ++k) rows[k] = static_cast<int>(A);
  return rows;
}

}  // namespace

AggregationMultigrid::AggregationMultigrid(const BlockMatrixGraph& fine_graph, const WeightedGraph& strength,
                                           const AggregationMultigridSettings& settings)
    : settings_(settings) {
  ProfilingRegion region("rouleau::AggregationMultigrid::hierarchy");
  std::vector<int> offsets, neighbors;
  host_node_graph(fine_graph, offsets, neighbors);
  WeightedGraph level_strength = strength;
  BlockMatrixGraph graph = fine_graph;
  for (;;) {
    auto level = std::make_unique<Level>();
    const int nodes = static_cast<int>(offsets.size()) - 1;
    level->graph = graph;
    level->block_row = device_copy(block_rows(offsets), "rouleau::AggregationMultigrid::block_row");
    const std::size_t rows = 4 * static_cast<std::size_t>(nodes);
    level->residual = DoubleView("rouleau::AggregationMultigrid::residual", rows);
    level->correction = DoubleView("rouleau::AggregationMultigrid::correction", rows);
    if (!levels_.empty()) {  // the finest level uses the fine values and apply()'s r and z
      level->rhs = DoubleView("rouleau::AggregationMultigrid::rhs", rows);
      level->solution = DoubleView("rouleau::AggregationMultigrid::solution", rows);
      level->values = DoubleView("rouleau::AggregationMultigrid::values", graph.entries.extent(0));
    }
    const bool last = nodes <= settings_.coarsest_nodes || static_cast<int>(levels_.size()) + 1 >= settings_.max_levels;
    if (!last) {
      Aggregation aggregation = aggregate_pairwise(level_strength, settings_.pairwise_passes);
      if (aggregation.num_aggregates > 0.9 * nodes) {
        levels_.push_back(std::move(level));  // coarsening stalled: solve this level
        break;
      }
      const int coarse_nodes = aggregation.num_aggregates;
      const std::vector<int>& aggregate_of = aggregation.aggregate_of;
      // Coarse node graph: I couples to J when a node of I couples to a node of J.
      std::vector<std::vector<int>> coupled(coarse_nodes);
      for (int a = 0; a < nodes; ++a)
        for (int k = offsets[a]; k < offsets[a + 1]; ++k) coupled[aggregate_of[a]].push_back(aggregate_of[neighbors[k]]);
      std::vector<int> coarse_offsets, coarse_neighbors;
      flatten_node_lists(coupled, coarse_offsets, coarse_neighbors);
      // Each fine block (a, b) adds to the coarse block (I(a), I(b)).
      std::vector<int> target(neighbors.size()), count(coarse_neighbors.size() + 1, 0);
      for (int a = 0; a < nodes; ++a) {
        const int I = aggregate_of[a];
        for (int k = offsets[a]; k < offsets[a + 1]; ++k) {
          const int J = aggregate_of[neighbors[k]];
          const auto first = coarse_neighbors.begin() + coarse_offsets[I];
          const auto found = std::lower_bound(first, coarse_neighbors.begin() + coarse_offsets[I + 1], J);
          target[k] = static_cast<int>(found - coarse_neighbors.begin());
          ++count[target[k] + 1];
        }
      }
      for (std::size_t c = 0; c + 1 < count.size(); ++c) count[c + 1] += count[c];
      std::vector<int> contributions(neighbors.size()), fill(count.begin(), count.end() - 1);
      for (std::size_t k = 0; k < neighbors.size(); ++k) contributions[fill[target[k]]++] = static_cast<int>(k);
      std::vector<int> member_offsets(coarse_nodes + 1, 0), members(nodes);
      for (int a = 0; a < nodes; ++a) ++member_offsets[aggregate_of[a] + 1];
      for (int I = 0; I < coarse_nodes; ++I) member_offsets[I + 1] += member_offsets[I];
      std::vector<int> next(member_offsets.begin(), member_offsets.end() - 1);
      for (int a = 0; a < nodes; ++a) members[next[aggregate_of[a]]++] = a;

      level->aggregate_of = device_copy(aggregate_of, "rouleau::AggregationMultigrid::aggregate_of");
      level->member_offsets = device_copy(member_offsets, "rouleau::AggregationMultigrid::member_offsets");
      level->members = device_copy(members, "rouleau::AggregationMultigrid::members");
      level->contribution_offsets = device_copy(count, "rouleau::AggregationMultigrid::contribution_offsets");
      level->contributions = device_copy(contributions, "rouleau::AggregationMultigrid::contributions");
      if (settings_.smoother == MultigridSmoother::ilu0) {
        level->smoother = std::make_unique<Ilu0Preconditioner>(graph.row_map, graph.entries);
      } else {
        level->smoother =
            std::make_unique<BlockJacobiSmoother>(graph, settings_.jacobi_sweeps, settings_.jacobi_damping_times_radius);
        if (settings_.precision == MultigridPrecision::single_precision)
          level->rounded_values = FloatView("rouleau::AggregationMultigrid::rounded_values", graph.entries.extent(0));
      }
      levels_.push_back(std::move(level));

      graph = make_block_matrix_graph(coarse_offsets, coarse_neighbors);
      offsets = std::move(coarse_offsets);
      neighbors = std::move(coarse_neighbors);
      level_strength = std::move(aggregation.coarse_graph);
      continue;
    }
    levels_.push_back(std::move(level));
    break;
  }
  // The coarsest level's sparse LU: the pattern is analysed once.
  coarsest_ = std::make_unique<CoarsestSolver>();
  const Level& last = *levels_.back();
  auto row_map = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), last.graph.row_map);
  auto entries = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), last.graph.entries);
  coarsest_->lu = std::make_unique<SparseDirectSolver>(
      last.graph.num_rows, std::vector<std::size_t>(row_map.data(), row_map.data() + row_map.extent(0)),
      std::vector<int>(entries.data(), entries.data() + entries.extent(0)));
  coarsest_->rhs = Kokkos::View<double*>::HostMirror("rouleau::AggregationMultigrid::coarsest_rhs", last.graph.num_rows);
  coarsest_->solution =
      Kokkos::View<double*>::HostMirror("rouleau::AggregationMultigrid::coarsest_solution", last.graph.num_rows);
  coarsest_->values.resize(entries.extent(0));
}

AggregationMultigrid::~AggregationMultigrid() = default;

void AggregationMultigrid::set_values(const Kokkos::View<double*>& fine_values) {
  ProfilingRegion region("rouleau::AggregationMultigrid::numeric");
  levels_.front()->values = fine_values;
  for (std::size_t l = 0; l + 1 < levels_.size(); ++l) {
    const Level& fine = *levels_[l];
    const Level& coarse = *levels_[l + 1];
    if (fine.rounded_values.extent(0) > 0) {
      const DoubleView values = fine.values;
      const FloatView rounded = fine.rounded_values;
      Kokkos::parallel_for(
          "rouleau::AggregationMultigrid::round", rounded.extent(0),
          KOKKOS_LAMBDA(const std::size_t e) { rounded(e) = static_cast<float>(values(e)); });
    }
    fine.smoother->factor(fine.values, fine.rounded_values);
    // A_{l+1}(I, J) = Σ_{a∈I, b∈J} A_l(a, b), block by block.
    const IntView fine_offsets = fine.graph.node_offsets, fine_rows = fine.block_row;
    const IntView coarse_offsets = coarse.graph.node_offsets, coarse_rows = coarse.block_row;
    const IntView contribution_offsets = fine.contribution_offsets, contributions = fine.contributions;
    const DoubleView fine_values_l = fine.values, coarse_values = coarse.values;
    Kokkos::parallel_for(
        "rouleau::AggregationMultigrid::galerkin", coarse_rows.extent(0), KOKKOS_LAMBDA(const int c) {
          const int I = coarse_rows(c);
          for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
              double sum = 0.0;
              for (int t = contribution_offsets(c); t < contribution_offsets(c + 1); ++t) {
                const int k = contributions(t);
                sum += fine_values_l(block_entry(fine_offsets, fine_rows(k), k, i, j));
              }
              coarse_values(block_entry(coarse_offsets, I, c, i, j)) = sum;
            }
        });
  }
  // The coarsest level: numeric LU on the host.
  auto values = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), levels_.back()->values);
  std::copy(values.data(), values.data() + values.extent(0), coarsest_->values.begin());
  coarsest_->lu->factor(coarsest_->values);
}

namespace {

// residual = rhs − A x on a level's matrix, node block by node block.
template <class Values>
void block_residual(const BlockMatrixGraph& graph, const Values& values, const ConstView& rhs, const DoubleView& x,
                    const DoubleView& residual) {
  const IntView offsets = graph.node_offsets, neighbors = graph.node_neighbors;
  Kokkos::parallel_for(
      "rouleau::AggregationMultigrid::residual", graph.num_rows / 4, KOKKOS_LAMBDA(const int A) {
        double node_residual[4];
        node_block_residual(offsets, neighbors, values, rhs, false, x, false, A, node_residual);
        for (int i = 0; i < 4; ++i) residual(4 * A + i) = node_residual[i];
      });
}

// b_c = Pᵀ r: each coarse node sums its members' residuals.
void restrict_to_coarse(const IntView& member_offsets, const IntView& members, const DoubleView& residual,
                        const DoubleView& coarse_rhs) {
  Kokkos::parallel_for(
      "rouleau::AggregationMultigrid::restrict", member_offsets.extent(0) - 1, KOKKOS_LAMBDA(const int I) {
        for (int i = 0; i < 4; ++i) {
          double sum = 0.0;
          for (int m = member_offsets(I); m < member_offsets(I + 1); ++m) sum += residual(4 * members(m) + i);
          coarse_rhs(4 * I + i) = sum;
        }
      });
}

// x += P x_c.
void prolong_and_add(const IntView& aggregate_of, const DoubleView& coarse_solution,
                     const DoubleView& solution) {
  Kokkos::parallel_for(
      "rouleau::AggregationMultigrid::prolong", aggregate_of.extent(0), KOKKOS_LAMBDA(const int a) {
        for (int i = 0; i < 4; ++i) solution(4 * a + i) += coarse_solution(4 * aggregate_of(a) + i);
      });
}

// x += c.
void add(const DoubleView& correction, const DoubleView& solution) {
  Kokkos::parallel_for(
      "rouleau::AggregationMultigrid::correct", solution.extent(0),
      KOKKOS_LAMBDA(const int row) { solution(row) += correction(row); });
}

}  // namespace

// residual = rhs − A x with the values the level's smoother reads.
void AggregationMultigrid::level_residual(int l, const Kokkos::View<const double*>& rhs,
                                          const Kokkos::View<double*>& x) const {
  const Level& level = *levels_[l];
  with_values_read(level.values, level.rounded_values,
                   [&](const auto& values_read) { block_residual(level.graph, values_read, rhs, x, level.residual); });
}

void AggregationMultigrid::cycle(int l, const Kokkos::View<const double*>& rhs,
                                 const Kokkos::View<double*>& solution) const {
  const Level& level = *levels_[l];
  if (l + 1 == num_levels()) {
    Kokkos::deep_copy(coarsest_->rhs, rhs);
    coarsest_->lu->solve(coarsest_->rhs.data(), coarsest_->solution.data());
    Kokkos::deep_copy(solution, coarsest_->solution);
    return;
  }
  const Level& coarse = *levels_[l + 1];
  // Pre-smoothing from x = 0: x = S⁻¹ b.
  level.smoother->apply(rhs, solution);
  // The coarse-grid correction, `cycle_index` times (1: V-cycle, 2: W-cycle).
  for (int visit = 0; visit < settings_.cycle_index; ++visit) {
    level_residual(l, rhs, solution);
    restrict_to_coarse(level.member_offsets, level.members, level.residual, coarse.rhs);
    cycle(l + 1, coarse.rhs, coarse.solution);
    prolong_and_add(level.aggregate_of, coarse.solution, solution);
  }
  // Post-smoothing: x += S⁻¹ (b − A x).
  level_residual(l, rhs, solution);
  level.smoother->apply(level.residual, level.correction);
  add(level.correction, solution);
}

void AggregationMultigrid::apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const {
  ProfilingRegion region("rouleau::AggregationMultigrid::cycle");
  // The finest level works on r and z themselves: no copies per GMRES iteration.
  cycle(0, r, z);
}

std::vector<int> AggregationMultigrid::level_nodes() const {
  std::vector<int> nodes;
  for (const auto& level : levels_) nodes.push_back(level->graph.num_rows / 4);
  return nodes;
}

std::vector<std::size_t> AggregationMultigrid::level_entries() const {
  std::vector<std::size_t> entries;
  for (const auto& level : levels_) entries.push_back(level->graph.entries.extent(0));
  return entries;
}

const BlockMatrixGraph& AggregationMultigrid::level_graph(int l) const { return levels_.at(l)->graph; }

Kokkos::View<double*> AggregationMultigrid::level_values(int l) const { return levels_.at(l)->values; }

Kokkos::View<float*> AggregationMultigrid::level_rounded_values(int l) const { return levels_.at(l)->rounded_values; }

std::vector<int> AggregationMultigrid::level_aggregates(int l) const {
  const IntView& aggregate_of = levels_.at(l)->aggregate_of;
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), aggregate_of);
  return std::vector<int>(host.data(), host.data() + host.extent(0));
}

double AggregationMultigrid::level_jacobi_damping(const int l) const {
  const auto* jacobi = dynamic_cast<const BlockJacobiSmoother*>(levels_.at(l)->smoother.get());
  return jacobi ? jacobi->damping() : 0.0;
}

std::string AggregationMultigrid::describe() const {
  std::ostringstream out;
  out << "aggregation multigrid, " << num_levels() << " levels of";
  for (std::size_t l = 0; l < levels_.size(); ++l) out << (l ? " → " : " ") << levels_[l]->graph.num_rows / 4;
  out << " nodes";
  return out.str();
}

}  // namespace rouleau
