#include "cells/surface_interaction.hpp"

#include <Kokkos_Sort.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <type_traits>

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
  cell_first_point_.assign(cells.num_cells() + 1, 0);
  for (const Point& point : points) ++cell_first_point_[point.cell + 1];
  std::partial_sum(cell_first_point_.begin(), cell_first_point_.end(), cell_first_point_.begin());
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
  cell_first_point_device_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::cell_first_point", cells.num_cells() + 1);
  auto h_first = Kokkos::create_mirror_view(cell_first_point_device_);
  for (int c = 0; c <= cells.num_cells(); ++c) h_first(c) = cell_first_point_[c];
  Kokkos::deep_copy(cell_first_point_device_, h_first);

  forces_ = PointVectors("rouleau::SurfaceInteraction::forces", n_points);
  positions_at_build_ = PointVectors("rouleau::SurfaceInteraction::positions_at_build", n_points);
  cell_boxes_ = Kokkos::View<double* [6]>("rouleau::SurfaceInteraction::cell_boxes", cells.num_cells());
  point_active_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::point_active", n_points);
  neighbor_offsets_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::neighbor_offsets", n_points + 1);
  neighbors_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::neighbors", 0);
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
  if (!built_) return true;
  // max_i |x_i − x_i(build)|² against (skin/2)²
  auto point_positions = point_positions_;
  auto at_build = positions_at_build_;
  double largest = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::SurfaceInteraction::largest_displacement", Kokkos::RangePolicy<ExecSpace>(0, num_points()),
      KOKKOS_LAMBDA(const int i, double& value) {
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c) {
          const double d = point_positions(i, c) - at_build(i, c);
          d2 += d * d;
        }
        if (d2 > value) value = d2;
      },
      Kokkos::Max<double>(largest));
  return largest > 0.25 * skin_ * skin_;
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::share_rows(const std::vector<int>& cells) {
  std::vector<int> rows(cells_.num_cells(), 0);
  for (const int c : cells) {
    if (c < 0 || c >= cells_.num_cells())
      throw std::invalid_argument("rouleau::SurfaceInteraction::share_rows: cell " + std::to_string(c) + " of " +
                                  std::to_string(cells_.num_cells()));
    rows[c] = 1;
  }
  row_cells_ = device_copy(rows, "rouleau::SurfaceInteraction::row_cells");
  row_cells_host_ = rows;
  rows_shared_ = true;
  built_ = false;  // the next force evaluation builds the list with these rows
  linearized_ = false;
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::rebuild() {
  ProfilingRegion region("rouleau::SurfaceInteraction::rebuild");
  const int n_points = num_points();
  const int n_cells = cells_.num_cells();
  auto point_positions = point_positions_;
  auto point_cell = point_cell_;

  // Broad phase: each cell's bounding box, then the pairs of cells whose boxes grown by
  // the search radius meet, by sweep and prune along x (sorted by lower x; O(N log N + K)).
  // With shared rows only the pairs with a cell of the rows count: the other cells' points
  // are left out of the bins.
  auto boxes = cell_boxes_;
  auto first_point = cell_first_point_device_;
  Kokkos::parallel_for(
      "rouleau::SurfaceInteraction::cell_boxes", Kokkos::RangePolicy<ExecSpace>(0, n_cells),
      KOKKOS_LAMBDA(const int c) {
        double lower[3] = {1e300, 1e300, 1e300}, upper[3] = {-1e300, -1e300, -1e300};
        for (int i = first_point(c); i < first_point(c + 1); ++i)
          for (int d = 0; d < 3; ++d) {
            const double x = point_positions(i, d);
            lower[d] = x < lower[d] ? x : lower[d];
            upper[d] = x > upper[d] ? x : upper[d];
          }
        for (int d = 0; d < 3; ++d) {
          boxes(c, d) = lower[d];
          boxes(c, 3 + d) = upper[d];
        }
      });
  auto host_boxes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cell_boxes_);
  std::vector<int> order(n_cells);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return host_boxes(a, 0) < host_boxes(b, 0); });
  std::vector<char> cell_active(n_cells, 0);
  const double reach = search_radius_;
  for (int a = 0; a < n_cells; ++a) {
    const int p = order[a];
    if (cell_first_point_[p + 1] == cell_first_point_[p]) continue;
    for (int b = a + 1; b < n_cells; ++b) {
      const int q = order[b];
      if (host_boxes(q, 0) > host_boxes(p, 3) + reach) break;
      bool meet = true;
      for (int d = 1; d < 3; ++d)
        meet = meet && host_boxes(q, d) <= host_boxes(p, 3 + d) + reach && host_boxes(p, d) <= host_boxes(q, 3 + d) + reach;
      // A shared list (share_rows) needs only the pairs with a cell of its rows.
      if (meet && (!rows_shared_ || row_cells_host_[p] || row_cells_host_[q])) cell_active[p] = cell_active[q] = 1;
    }
  }
  Kokkos::View<int*> active_cells("rouleau::SurfaceInteraction::cell_active", n_cells);
  auto host_active = Kokkos::create_mirror_view(active_cells);
  double lower[3] = {1e300, 1e300, 1e300}, upper[3] = {-1e300, -1e300, -1e300};
  active_cells_ = 0;
  for (int c = 0; c < n_cells; ++c) {
    host_active(c) = cell_active[c];
    if (!cell_active[c]) continue;
    ++active_cells_;
    for (int d = 0; d < 3; ++d) {
      lower[d] = std::min(lower[d], host_boxes(c, d));
      upper[d] = std::max(upper[d], host_boxes(c, 3 + d));
    }
  }
  Kokkos::deep_copy(active_cells, host_active);
  auto point_active = point_active_;
  Kokkos::parallel_for(
      "rouleau::SurfaceInteraction::point_active", Kokkos::RangePolicy<ExecSpace>(0, n_points),
      KOKKOS_LAMBDA(const int i) { point_active(i) = active_cells(point_cell(i)); });

  // The bins: half the search radius (searched two deep), over the active cells' boxes,
  // at most about 8 per point (larger bins then).
  BinGrid grid{};
  grid.bin_size = 0.5 * search_radius_;
  if (active_cells_ == 0) {
    for (int d = 0; d < 3; ++d) lower[d] = upper[d] = 0.0;
  }
  double bin_count = 1.0;
  for (int d = 0; d < 3; ++d) bin_count *= std::max(1.0, std::ceil((upper[d] - lower[d]) / grid.bin_size));
  const double most_bins = std::max(27.0, 8.0 * n_points);
  if (bin_count > most_bins) grid.bin_size *= std::cbrt(bin_count / most_bins);
  for (int d = 0; d < 3; ++d) {
    grid.lower[d] = lower[d];
    grid.bins[d] = std::max(1, static_cast<int>(std::ceil((upper[d] - lower[d]) / grid.bin_size)));
  }
  grid.reach = static_cast<int>(std::ceil(search_radius_ / grid.bin_size - 1e-12));
  grid_ = grid;
  const int n_bins = grid.num_bins();

  // Active points sorted by (bin, index): key = bin · N + i.
  Kokkos::View<std::int64_t*> keys("rouleau::SurfaceInteraction::keys", n_points);
  int n_active = 0;
  Kokkos::parallel_scan(
      "rouleau::SurfaceInteraction::bin_keys", Kokkos::RangePolicy<ExecSpace>(0, n_points),
      KOKKOS_LAMBDA(const int i, int& slot, const bool final) {
        if (!point_active(i)) return;
        if (final) {
          const double x[3] = {point_positions(i, 0), point_positions(i, 1), point_positions(i, 2)};
          keys(slot) = static_cast<std::int64_t>(grid.bin_of(x)) * n_points + i;
        }
        ++slot;
      },
      n_active);
  keys = Kokkos::subview(keys, std::make_pair(0, n_active));
  Kokkos::sort(keys);
  if (static_cast<int>(bin_offsets_.extent(0)) != n_bins + 1)
    bin_offsets_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::bin_offsets", n_bins + 1);
  if (static_cast<int>(sorted_points_.extent(0)) < n_active)
    sorted_points_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::sorted_points", n_active);
  auto bin_offsets = bin_offsets_;
  auto sorted_points = sorted_points_;
  Kokkos::deep_copy(bin_offsets, 0);
  Kokkos::parallel_for(
      "rouleau::SurfaceInteraction::bin_counts", Kokkos::RangePolicy<ExecSpace>(0, n_active),
      KOKKOS_LAMBDA(const int k) {
        sorted_points(k) = static_cast<int>(keys(k) % n_points);
        Kokkos::atomic_add(&bin_offsets(static_cast<int>(keys(k) / n_points) + 1), 1);
      });
  Kokkos::parallel_scan(
      "rouleau::SurfaceInteraction::bin_offsets", Kokkos::RangePolicy<ExecSpace>(0, n_bins + 1),
      KOKKOS_LAMBDA(const int b, int& sum, const bool final) {
        sum += bin_offsets(b);
        if (final) bin_offsets(b) = sum;
      });

  // The list: count, scan, fill.
  const double radius_squared = search_radius_ * search_radius_;
  auto offsets = neighbor_offsets_;
  const bool half = half_list_;
  // The rows this rank builds (share_rows): points of its cells.
  const bool shared = rows_shared_;
  auto row_cells = row_cells_;
  auto builds_row = KOKKOS_LAMBDA(const int i) { return point_active(i) && (!shared || row_cells(point_cell(i))); };
  // A share of the rows takes the balanced half list (kernels/surface_neighbors.hpp).
  const bool balanced = half && shared;
  auto count_row = KOKKOS_LAMBDA(const int i, int& count) {
    auto visit = [&](int) { ++count; };
    if (balanced)
      for_each_neighbor<BalancedHalfList>(i, grid, radius_squared, point_positions, point_cell, bin_offsets,
                                          sorted_points, visit);
    else if (half)
      for_each_neighbor<HalfList>(i, grid, radius_squared, point_positions, point_cell, bin_offsets, sorted_points,
                                  visit);
    else
      for_each_neighbor<FullList>(i, grid, radius_squared, point_positions, point_cell, bin_offsets, sorted_points,
                                  visit);
  };
  Kokkos::parallel_for(
      "rouleau::SurfaceInteraction::count_neighbors", Kokkos::RangePolicy<ExecSpace>(0, n_points + 1),
      KOKKOS_LAMBDA(const int i) {
        int count = 0;
        if (i < n_points && builds_row(i)) count_row(i, count);
        offsets(i) = count;
      });
  int entries = 0;
  Kokkos::parallel_scan(
      "rouleau::SurfaceInteraction::neighbor_offsets", Kokkos::RangePolicy<ExecSpace>(0, n_points + 1),
      KOKKOS_LAMBDA(const int i, int& sum, const bool final) {
        const int count = offsets(i);
        if (final) offsets(i) = sum;
        sum += count;
      },
      entries);
  list_entries_ = entries;
  if (static_cast<int>(neighbors_.extent(0)) < entries)
    neighbors_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::neighbors", entries + entries / 5);
  auto neighbors = neighbors_;
  Kokkos::parallel_for(
      "rouleau::SurfaceInteraction::fill_neighbors", Kokkos::RangePolicy<ExecSpace>(0, n_points),
      KOKKOS_LAMBDA(const int i) {
        if (!builds_row(i)) return;
        int slot = offsets(i);
        auto visit = [&](int j) { neighbors(slot++) = j; };
        if (balanced)
          for_each_neighbor<BalancedHalfList>(i, grid, radius_squared, point_positions, point_cell, bin_offsets,
                                              sorted_points, visit);
        else if (half)
          for_each_neighbor<HalfList>(i, grid, radius_squared, point_positions, point_cell, bin_offsets,
                                      sorted_points, visit);
        else
          for_each_neighbor<FullList>(i, grid, radius_squared, point_positions, point_cell, bin_offsets,
                                      sorted_points, visit);
      });

  auto at_build = positions_at_build_;
  Kokkos::parallel_for(
      "rouleau::SurfaceInteraction::positions_at_build", Kokkos::RangePolicy<ExecSpace>(0, n_points),
      KOKKOS_LAMBDA(const int i) {
        for (int c = 0; c < 3; ++c) at_build(i, c) = point_positions(i, c);
      });
  // The cells of the list's rows and columns.
  if (static_cast<int>(cells_in_list_.extent(0)) != n_cells)
    cells_in_list_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::cells_in_list", n_cells);
  else
    Kokkos::deep_copy(cells_in_list_, 0);
  auto in_list = cells_in_list_;
  Kokkos::parallel_for(
      "rouleau::SurfaceInteraction::cells_in_list", Kokkos::RangePolicy<ExecSpace>(0, n_points),
      KOKKOS_LAMBDA(const int i) {
        if (offsets(i + 1) == offsets(i)) return;
        Kokkos::atomic_fetch_max(&in_list(point_cell(i)), 1);
        for (int k = offsets(i); k < offsets(i + 1); ++k) Kokkos::atomic_fetch_max(&in_list(point_cell(neighbors(k))), 1);
      });
  built_ = true;
  ++rebuilds_;
  ++list_version_;
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
                                                                     potentials_,     neighbor_offsets_, neighbors_,
                                                                     forces_,         force_scatter_,  rows};
    launch(pairs, Kokkos::RangePolicy<ExecSpace, Tag>(0, rows.extent()));
    gather_into(forces_, force_scatter_);
  } else {
    launch(SurfacePairForceFunctor<FullList, MorsePotential, Scatter>{point_positions_, point_weight_, point_kind_,
                                                                      potentials_, neighbor_offsets_, neighbors_,
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
  Stiffness stiffness{linearized_positions_, point_weight_,  point_kind_,     potentials_,      neighbor_offsets_,
                      neighbors_,            pair_offsets_, pair_neighbors_, pair_coefficients_};
  Kokkos::parallel_for("rouleau::SurfaceInteraction::count_pairs_in_range",
                       Kokkos::RangePolicy<ExecSpace, CountPairsInRange>(0, n_points), stiffness);
  auto offsets = pair_offsets_;
  int pairs = 0;
  Kokkos::parallel_scan(
      "rouleau::SurfaceInteraction::pair_offsets", Kokkos::RangePolicy<ExecSpace>(0, n_points + 1),
      KOKKOS_LAMBDA(const int i, int& sum, const bool final) {
        const int count = i < n_points ? offsets(i) : 0;
        if (final) offsets(i) = sum;
        sum += count;
      },
      pairs);
  if (static_cast<int>(pair_neighbors_.extent(0)) < pairs) {
    pair_neighbors_ = Kokkos::View<int*>("rouleau::SurfaceInteraction::pair_neighbors", pairs + pairs / 5);
    pair_coefficients_ = Kokkos::View<double* [2]>("rouleau::SurfaceInteraction::pair_coefficients", pairs + pairs / 5);
  }
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
  data.integers["interaction/list_built"] = {built_ ? 1 : 0};
  data.integers["interaction/rebuilds"] = {rebuilds_};
  if (built_) data.reals["interaction/positions_at_build"] = to_flat_vector(positions_at_build_);
}

template <class ExecSpace>
void BasicSurfaceInteraction<ExecSpace>::restore_state(const CheckpointData& data) {
  const bool built = data.integer("interaction/list_built", 1).front() != 0;
  const int rebuilds = static_cast<int>(data.integer("interaction/rebuilds", 1).front());
  if (built) {
    // The list as it was built: from the points' positions of that moment.
    from_flat_vector(data.real("interaction/positions_at_build", 3LL * num_points()), point_positions_,
                     "interaction/positions_at_build");
    rebuild();
  } else {
    built_ = false;
  }
  rebuilds_ = rebuilds;
  linearized_ = false;  // the pairs in range belong to positions before the restore
  gather_point_positions();
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicSurfaceInteraction)

}  // namespace rouleau
