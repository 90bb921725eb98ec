#include "cells/surface_interaction.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <type_traits>

#include "kernels/csr_rows.hpp"
#include "kernels/morse_pairs.hpp"
#include "kernels/morse_stiffness.hpp"
#include "kernels/scatter_sum.hpp"
#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"
#include "util/view_transfer.hpp"

namespace rouleau {

namespace {
// points(p) = Σ_k s_pk nodes(n_pk): node vectors at the surface points
template <class ExecSpace, class NodeVectors, class PointVectors>
void nodes_to_points(const NodeVectors& nodes, const Kokkos::View<int* [3]>& point_nodes,
                     const Kokkos::View<double* [3]>& point_shape, const PointVectors& points) {
  Kokkos::parallel_for(
      "rouleau::SurfaceInteraction::nodes_to_points", Kokkos::RangePolicy<ExecSpace>(0, points.extent(0)),
      KOKKOS_LAMBDA(const int p) {
        for (int c = 0; c < 3; ++c)
          points(p, c) = point_shape(p, 0) * nodes(point_nodes(p, 0), c) +
                         point_shape(p, 1) * nodes(point_nodes(p, 1), c) + point_shape(p, 2) * nodes(point_nodes(p, 2), c);
      });
}

// nodes(n) = Σ_{p, k: n_pk = n} s_pk points(p): point forces on to the nodes
template <class ExecSpace, class PointVectors, class Scatter>
void points_to_nodes(const PointVectors& points, const Kokkos::View<int* [3]>& point_nodes,
                     const Kokkos::View<double* [3]>& point_shape, Scatter& scatter, const PointVectors& nodes) {
  scatter.reset();
  Kokkos::parallel_for(
      "rouleau::SurfaceInteraction::points_to_nodes", Kokkos::RangePolicy<ExecSpace>(0, points.extent(0)),
      KOKKOS_LAMBDA(const int p) {
        auto access = scatter.access();
        for (int k = 0; k < 3; ++k)
          if (point_shape(p, k) != 0.0)
            for (int c = 0; c < 3; ++c) access(point_nodes(p, k), c) += point_shape(p, k) * points(p, c);
      });
  gather_into(nodes, scatter);
}

// On host threads the half list's rows run in blocks of 64, interleaved with stride 64
// (InterleavedRows) over a static partition: balanced threads, and the same sums in the
// same order on every run and restart with a given thread count (dynamic
// scheduling balanced them too but regrouped the sums run to run). On a GPU each row is a
// thread anyway: the plain order keeps neighbouring rows together.
template <class ExecSpace>
InterleavedRows half_list_rows(const int num_points) {
  // host threads: the execution space runs on the host (not a GPU with host-visible memory)
  constexpr bool on_host = Kokkos::SpaceAccessibility<ExecSpace, Kokkos::HostSpace>::accessible;
  return {num_points, on_host ? 64 : 1, on_host ? 64 : 1};
}
}  // namespace

template <class ExecSpace>
BasicSurfaceInteraction<ExecSpace>::BasicSurfaceInteraction(const Population& cells,
                                                            const std::vector<int>& cell_kind, int num_kinds,
                                                            const std::vector<MorsePotential>& potentials,
                                                            double skin, bool half_list,
                                                            SurfaceQuadrature quadrature)
    : cells_(cells), num_kinds_(num_kinds), skin_(skin), half_list_(half_list) {
  if (static_cast<int>(cell_kind.size()) != cells.num_cells())
    throw std::invalid_argument("rouleau::SurfaceInteraction: one kind per cell expected");
  if (static_cast<int>(potentials.size()) != num_kinds * num_kinds)
    throw std::invalid_argument("rouleau::SurfaceInteraction: one potential per pair of kinds expected");
  if (!(skin > 0.0)) throw std::invalid_argument("rouleau::SurfaceInteraction: the skin must be > 0");
  ProfilingRegion region("rouleau::SurfaceInteraction::setup");
  potentials_ = Kokkos::View<MorsePotential**>("rouleau::SurfaceInteraction::potentials", num_kinds, num_kinds);
  auto host_potentials = Kokkos::create_mirror_view(potentials_);
  max_cutoff_ = 0.0;
  for (int a = 0; a < num_kinds; ++a)
    for (int b = 0; b < num_kinds; ++b) {
      host_potentials(a, b) = potentials[a * num_kinds + b];
      max_cutoff_ = std::max(max_cutoff_, potentials[a * num_kinds + b].cutoff);
    }
  Kokkos::deep_copy(potentials_, host_potentials);
  search_radius_ = max_cutoff_ + skin_;

  // The surface points, cell by cell: the nodes with an outer-surface area weight (nodal
  // quadrature), or the rule's points on each outer-surface triangle with weight A_t w_q
  // (A_t on the reference surface).
  struct Point {
    std::array<int, 3> nodes;
    std::array<double, 3> shape;
    double weight;
    int cell;
  };
  std::vector<Point> points;
  auto node_cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.node_cell());
  if (quadrature == SurfaceQuadrature::nodes) {
    auto weights = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.surface_area_weights());
    for (int n = 0; n < cells.num_nodes(); ++n)
      if (weights(n) > 0.0) points.push_back({{n, n, n}, {1.0, 0.0, 0.0}, weights(n), node_cell(n)});
  } else {
    const std::vector<TrianglePoint> rule = triangle_rule(quadrature);
    auto triangles = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.surface_triangles());
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.reference_positions());
    for (std::size_t t = 0; t < triangles.extent(0); ++t) {
      const std::array<int, 3> nodes{triangles(t, 0), triangles(t, 1), triangles(t, 2)};
      auto corner = [&](int k) { return std::array<double, 3>{x(nodes[k], 0), x(nodes[k], 1), x(nodes[k], 2)}; };
      const double area = triangle_area(corner(0), corner(1), corner(2));
      for (const TrianglePoint& q : rule) points.push_back({nodes, q.barycentric, area * q.weight, node_cell(nodes[0])});
    }
  }
  std::vector<int> cell_first_point(cells.num_cells() + 1, 0);
  for (const Point& point : points) ++cell_first_point[point.cell + 1];
  std::partial_sum(cell_first_point.begin(), cell_first_point.end(), cell_first_point.begin());
  const int n_points = static_cast<int>(points.size());
  point_nodes_ = Kokkos::View<int* [3]>("rouleau::SurfaceInteraction::point_nodes", n_points);
  point_shape_ = Kokkos::View<double* [3]>("rouleau::SurfaceInteraction::point_shape", n_points);
  point_cell_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::point_cell", n_points);
  point_kind_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::point_kind", n_points);
  point_weight_ = Kokkos::View<double*>("rouleau::SurfaceInteraction::point_weight", n_points);
  point_positions_ = PointVectors("rouleau::SurfaceInteraction::point_positions", n_points);
  auto h_nodes = Kokkos::create_mirror_view(point_nodes_);
  auto h_shape = Kokkos::create_mirror_view(point_shape_);
  auto h_cell = Kokkos::create_mirror_view(point_cell_);
  auto h_kind = Kokkos::create_mirror_view(point_kind_);
  auto h_weight = Kokkos::create_mirror_view(point_weight_);
  for (int i = 0; i < n_points; ++i) {
    for (int k = 0; k < 3; ++k) {
      h_nodes(i, k) = points[i].nodes[k];
      h_shape(i, k) = points[i].shape[k];
    }
    h_cell(i) = points[i].cell;
    h_kind(i) = cell_kind[h_cell(i)];
    if (h_kind(i) < 0 || h_kind(i) >= num_kinds)
      throw std::invalid_argument("rouleau::SurfaceInteraction: a cell kind index out of range");
    h_weight(i) = points[i].weight;
  }
  Kokkos::deep_copy(point_nodes_, h_nodes);
  Kokkos::deep_copy(point_shape_, h_shape);
  Kokkos::deep_copy(point_cell_, h_cell);
  Kokkos::deep_copy(point_kind_, h_kind);
  Kokkos::deep_copy(point_weight_, h_weight);
  forces_ = PointVectors("rouleau::SurfaceInteraction::forces", n_points);
  list_.emplace(cell_first_point, point_cell_, search_radius_, skin_, half_list_);
  if (half_list_) force_scatter_ = Scatter("rouleau::SurfaceInteraction::force_scatter", n_points);
  node_force_scatter_ = Scatter("rouleau::SurfaceInteraction::node_force_scatter", cells.num_nodes());
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::gather_point_positions() {
  // x_p = Σ_k s_pk x_{n_pk}
  nodes_to_points<ExecSpace>(cells_.positions(), point_nodes_, point_shape_, point_positions_);
}

template <class ExecSpace>
bool BasicSurfaceInteraction<ExecSpace>::list_is_stale() const {
  return list_->is_stale(point_positions_);
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::rebuild() {
  list_->build(point_positions_);
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::share_rows(const std::vector<int>& cells) {
  list_->share_rows(cells);
  linearized_ = false;
}

template <class ExecSpace>
template <class Tag>
double BasicSurfaceInteraction<ExecSpace>::run_pair_kernel(const char* label) {
  gather_point_positions();
  if (list_is_stale()) rebuild();
  ProfilingRegion region("rouleau::SurfaceInteraction::pair_forces");
  double energy = 0.0;
  auto launch = [&](const auto& pairs, const auto& policy) {
    if constexpr (std::is_same_v<Tag, ForcesAndEnergy>)
      Kokkos::parallel_reduce(label, policy, pairs, energy);
    else
      Kokkos::parallel_for(label, policy, pairs);
  };
  if (half_list_) {
    force_scatter_.reset();
    // A half list keeps the pairs j > i of points numbered cell by cell, so the first
    // cells' rows hold most of the pairs: they run interleaved on host threads.
    const InterleavedRows rows = half_list_rows<ExecSpace>(num_points());
    SurfacePairForceFunctor<HalfList, MorsePotential, Scatter> pairs{point_positions_, point_weight_, point_kind_,
                                                                     potentials_,     list_->offsets(), list_->neighbors(),
                                                                     forces_,         force_scatter_,  rows};
    launch(pairs, Kokkos::RangePolicy<ExecSpace, Tag>(0, rows.extent()));
    gather_into(forces_, force_scatter_);
  } else {
    launch(SurfacePairForceFunctor<FullList, MorsePotential, Scatter>{point_positions_, point_weight_, point_kind_,
                                                                      potentials_, list_->offsets(), list_->neighbors(),
                                                                      forces_, force_scatter_, {num_points(), 1}},
           Kokkos::RangePolicy<ExecSpace, Tag>(0, num_points()));
  }
  return energy;
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::compute_forces() {
  run_pair_kernel<ForcesOnly>("rouleau::SurfaceInteraction::pair_forces");
}

template <class ExecSpace>
double BasicSurfaceInteraction<ExecSpace>::compute_forces_and_energy() {
  return run_pair_kernel<ForcesAndEnergy>("rouleau::SurfaceInteraction::pair_forces_and_energy");
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::copy_forces_to_nodes(const PointVectors& node_forces) const {
  // f_n = Σ_{p, k: n_pk = n} s_pk F_p
  points_to_nodes<ExecSpace>(forces_, point_nodes_, point_shape_, node_force_scatter_, node_forces);
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::linearize() {
  gather_point_positions();
  if (list_is_stale()) rebuild();
  ProfilingRegion region("rouleau::SurfaceInteraction::linearize");
  const int n_points = num_points();
  if (linearized_positions_.extent(0) == 0) {
    linearized_positions_ = PointVectors("rouleau::SurfaceInteraction::linearized_positions", n_points);
    point_displacements_ = PointVectors("rouleau::SurfaceInteraction::point_displacements", n_points);
    point_force_changes_ = PointVectors("rouleau::SurfaceInteraction::point_force_changes", n_points);
    pair_offsets_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::pair_offsets", n_points + 1);
    if (half_list_) change_scatter_ = Scatter("rouleau::SurfaceInteraction::change_scatter", n_points);
  }
  Kokkos::deep_copy(linearized_positions_, point_positions_);
  // The pairs within the cut-off: count, scan, fill with their coefficients.
  using Stiffness = SurfacePairStiffnessFunctor<MorsePotential>;
  Stiffness stiffness{linearized_positions_, point_weight_,  point_kind_,     potentials_,      list_->offsets(),
                      list_->neighbors(),    pair_offsets_, pair_neighbors_, pair_coefficients_};
  Kokkos::parallel_for("rouleau::SurfaceInteraction::count_pairs_in_range",
                       Kokkos::RangePolicy<ExecSpace, CountPairsInRange>(0, n_points), stiffness);
  const int pairs = counts_to_offsets<ExecSpace>("rouleau::SurfaceInteraction::pair_offsets", pair_offsets_, n_points);
  ensure_length(pair_neighbors_, static_cast<std::size_t>(pairs), "rouleau::SurfaceInteraction::pair_neighbors");
  ensure_length(pair_coefficients_, static_cast<std::size_t>(pairs), "rouleau::SurfaceInteraction::pair_coefficients");
  stiffness.pair_neighbors = pair_neighbors_;
  stiffness.pair_coefficients = pair_coefficients_;
  Kokkos::parallel_for("rouleau::SurfaceInteraction::pair_stiffness",
                       Kokkos::RangePolicy<ExecSpace, FillPairsInRange>(0, n_points), stiffness);
  linearized_pairs_ = pairs;
  linearized_ = true;
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::force_change(const PointVectors& node_displacements,
                                                      const PointVectors& node_force_changes) const {
  if (!linearized_) throw std::logic_error("rouleau::SurfaceInteraction::force_change: linearize() first");
  ProfilingRegion region("rouleau::SurfaceInteraction::force_change");
  // δx_p = Σ_k s_pk δx_{n_pk}, then δF per point, then δf_n = Σ s_pk δF_p
  nodes_to_points<ExecSpace>(node_displacements, point_nodes_, point_shape_, point_displacements_);
  if (half_list_) {
    change_scatter_.reset();
    const InterleavedRows rows = half_list_rows<ExecSpace>(num_points());
    Kokkos::parallel_for("rouleau::SurfaceInteraction::pair_force_changes", Kokkos::RangePolicy<ExecSpace>(0, rows.extent()),
                         SurfacePairForceChangeFunctor<HalfList, Scatter>{linearized_positions_, point_displacements_,
                                                                          pair_offsets_, pair_neighbors_,
                                                                          pair_coefficients_, point_force_changes_,
                                                                          change_scatter_, rows});
    gather_into(point_force_changes_, change_scatter_);
  } else {
    Kokkos::parallel_for("rouleau::SurfaceInteraction::pair_force_changes", Kokkos::RangePolicy<ExecSpace>(0, num_points()),
                         SurfacePairForceChangeFunctor<FullList, Scatter>{linearized_positions_, point_displacements_,
                                                                          pair_offsets_, pair_neighbors_,
                                                                          pair_coefficients_, point_force_changes_,
                                                                          change_scatter_, {num_points(), 1}});
  }
  points_to_nodes<ExecSpace>(point_force_changes_, point_nodes_, point_shape_, node_force_scatter_, node_force_changes);
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::save_state(CheckpointData& data) const {
  list_->save_state(data);
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::restore_state(const CheckpointData& data) {
  list_->restore_state(data, point_positions_);
  linearized_ = false;  // the pairs in range belong to positions before the restore
  gather_point_positions();
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicSurfaceInteraction)

}  // namespace rouleau
