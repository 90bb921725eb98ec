#include "cells/surface_neighbor_list.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/box_overlaps.hpp"
#include "kernels/csr_rows.hpp"
#include "kernels/surface_neighbors.hpp"
#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"
#include "util/view_transfer.hpp"

namespace rouleau {

template <class ExecSpace>
BasicSurfaceNeighborList<ExecSpace>::BasicSurfaceNeighborList(const std::vector<int>& cell_first_point,
                                                              const Kokkos::View<int*>& point_cell,
                                                              const double search_radius, const double skin,
                                                              const bool half_list)
    : num_cells_(static_cast<int>(cell_first_point.size()) - 1),
      num_points_(static_cast<int>(point_cell.extent(0))),
      search_radius_(search_radius),
      skin_(skin),
      half_list_(half_list),
      cell_first_point_device_(device_copy(cell_first_point, "rouleau::SurfaceNeighborList::cell_first_point")),
      point_cell_(point_cell),
      positions_at_build_("rouleau::SurfaceNeighborList::positions_at_build", num_points_),
      cell_boxes_("rouleau::SurfaceNeighborList::cell_boxes", num_cells_),
      point_active_("rouleau::SurfaceNeighborList::point_active", num_points_),
      offsets_("rouleau::SurfaceNeighborList::offsets", num_points_ + 1),
      neighbors_("rouleau::SurfaceNeighborList::neighbors", 0) {}

template <class ExecSpace>
bool BasicSurfaceNeighborList<ExecSpace>::is_stale(const PointVectors& point_positions) const {
  if (!built_) return true;
  // max_i |x_i − x_i(build)|² against (skin/2)²
  auto at_build = positions_at_build_;
  double largest = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::SurfaceNeighborList::largest_displacement", Kokkos::RangePolicy<ExecSpace>(0, num_points_),
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
void BasicSurfaceNeighborList<ExecSpace>::share_rows(const std::vector<int>& cells) {
  std::vector<int> rows(num_cells_, 0);
  for (const int c : cells) {
    if (c < 0 || c >= num_cells_)
      throw std::invalid_argument("rouleau::SurfaceInteraction::share_rows: cell " + std::to_string(c) + " of " +
                                  std::to_string(num_cells_));
    rows[c] = 1;
  }
  row_cells_ = device_copy(rows, "rouleau::SurfaceNeighborList::row_cells");
  row_cells_host_ = rows;
  rows_shared_ = true;
  built_ = false;  // the next force evaluation builds the list with these rows
}

template <class ExecSpace>
void BasicSurfaceNeighborList<ExecSpace>::find_active_cells(const PointVectors& point_positions, double lower[3],
                                                           double upper[3]) {
  // Each cell's bounding box, then the pairs of cells whose boxes are at most the search
  // radius apart (geometry/box_overlaps.hpp). With shared rows only the pairs with a cell
  // of the rows count: the other cells' points are left out of the bins.
  auto boxes = cell_boxes_;
  auto first_point = cell_first_point_device_;
  Kokkos::parallel_for(
      "rouleau::SurfaceNeighborList::cell_boxes", Kokkos::RangePolicy<ExecSpace>(0, num_cells_),
      KOKKOS_LAMBDA(const int c) {
        double low[3] = {1e300, 1e300, 1e300}, high[3] = {-1e300, -1e300, -1e300};
        for (int i = first_point(c); i < first_point(c + 1); ++i)
          for (int d = 0; d < 3; ++d) {
            const double x = point_positions(i, d);
            low[d] = x < low[d] ? x : low[d];
            high[d] = x > high[d] ? x : high[d];
          }
        for (int d = 0; d < 3; ++d) {
          boxes(c, d) = low[d];
          boxes(c, 3 + d) = high[d];
        }
      });
  auto host_boxes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cell_boxes_);
  std::vector<Box> cell_box(num_cells_);
  for (int c = 0; c < num_cells_; ++c)
    for (int k = 0; k < 6; ++k) cell_box[c][k] = host_boxes(c, k);
  std::vector<int> cell_active(num_cells_, 0);
  for (const auto& [p, q] : boxes_within(cell_box, search_radius_))
    // A shared list (share_rows) needs only the pairs with a cell of its rows.
    if (!rows_shared_ || row_cells_host_[p] || row_cells_host_[q]) cell_active[p] = cell_active[q] = 1;
  for (int d = 0; d < 3; ++d) {
    lower[d] = 1e300;
    upper[d] = -1e300;
  }
  active_cells_ = 0;
  for (int c = 0; c < num_cells_; ++c) {
    if (!cell_active[c]) continue;
    ++active_cells_;
    for (int d = 0; d < 3; ++d) {
      lower[d] = std::min(lower[d], host_boxes(c, d));
      upper[d] = std::max(upper[d], host_boxes(c, 3 + d));
    }
  }
  if (active_cells_ == 0)
    for (int d = 0; d < 3; ++d) lower[d] = upper[d] = 0.0;
  const auto active_cells = device_copy(cell_active, "rouleau::SurfaceNeighborList::cell_active");
  auto point_active = point_active_;
  auto point_cell = point_cell_;
  Kokkos::parallel_for(
      "rouleau::SurfaceNeighborList::point_active", Kokkos::RangePolicy<ExecSpace>(0, num_points_),
      KOKKOS_LAMBDA(const int i) { point_active(i) = active_cells(point_cell(i)); });
}

template <class ExecSpace>
void BasicSurfaceNeighborList<ExecSpace>::fill_rows(const PointVectors& point_positions, const bool count_only) {
  const double radius_squared = search_radius_ * search_radius_;
  const auto bins = bins_;
  auto point_active = point_active_;
  auto point_cell = point_cell_;
  auto offsets = offsets_;
  auto neighbors = neighbors_;
  const bool half = half_list_;
  // The rows this rank builds (share_rows): points of its cells; a share of the rows
  // takes the balanced half list (kernels/surface_neighbors.hpp).
  const bool shared = rows_shared_;
  const bool balanced = half && shared;
  auto row_cells = row_cells_;
  Kokkos::parallel_for(
      count_only ? "rouleau::SurfaceNeighborList::count_neighbors" : "rouleau::SurfaceNeighborList::fill_neighbors",
      Kokkos::RangePolicy<ExecSpace>(0, num_points_), KOKKOS_LAMBDA(const int i) {
        int slot = count_only ? 0 : offsets(i);
        if (point_active(i) && (!shared || row_cells(point_cell(i)))) {
          auto visit = [&](const int j) {
            if (!count_only) neighbors(slot) = j;
            ++slot;
          };
          if (balanced)
            for_each_neighbor<BalancedHalfList>(i, bins, radius_squared, point_positions, point_cell, visit);
          else if (half)
            for_each_neighbor<HalfList>(i, bins, radius_squared, point_positions, point_cell, visit);
          else
            for_each_neighbor<FullList>(i, bins, radius_squared, point_positions, point_cell, visit);
        }
        if (count_only) offsets(i) = slot;
      });
}

template <class ExecSpace>
void BasicSurfaceNeighborList<ExecSpace>::build(const PointVectors& point_positions) {
  ProfilingRegion region("rouleau::SurfaceInteraction::rebuild");
  double lower[3], upper[3];
  find_active_cells(point_positions, lower, upper);

  // The bins: half the search radius (searched two deep), over the active cells' boxes,
  // at most about 8 per point (larger bins then).
  double width = 0.5 * search_radius_;
  double bin_count = 1.0;
  for (int d = 0; d < 3; ++d) bin_count *= std::max(1.0, std::ceil((upper[d] - lower[d]) / width));
  const double most_bins = std::max(27.0, 8.0 * num_points_);
  if (bin_count > most_bins) width *= std::cbrt(bin_count / most_bins);
  bins_.grid = cubic_bins_covering(lower, upper, width, static_cast<int>(std::ceil(search_radius_ / width - 1e-12)));
  auto point_active = point_active_;
  sort_into_bins<ExecSpace>(point_positions, num_points_, KOKKOS_LAMBDA(const int i) { return point_active(i) != 0; },
                            bins_);

  // The list: count, scan, fill.
  fill_rows(point_positions, true);
  entries_ = counts_to_offsets<ExecSpace>("rouleau::SurfaceNeighborList::offsets", offsets_, num_points_);
  ensure_length(neighbors_, static_cast<std::size_t>(entries_), "rouleau::SurfaceNeighborList::neighbors");
  fill_rows(point_positions, false);

  Kokkos::deep_copy(positions_at_build_, point_positions);
  // The cells of the list's rows and columns.
  zero_with_length(cells_in_list_, num_cells_, "rouleau::SurfaceNeighborList::cells_in_list");
  auto in_list = cells_in_list_;
  auto offsets = offsets_;
  auto neighbors = neighbors_;
  auto point_cell = point_cell_;
  Kokkos::parallel_for(
      "rouleau::SurfaceNeighborList::cells_in_list", Kokkos::RangePolicy<ExecSpace>(0, num_points_),
      KOKKOS_LAMBDA(const int i) {
        if (offsets(i + 1) == offsets(i)) return;
        Kokkos::atomic_fetch_max(&in_list(point_cell(i)), 1);
        for (int k = offsets(i); k < offsets(i + 1); ++k) Kokkos::atomic_fetch_max(&in_list(point_cell(neighbors(k))), 1);
      });
  built_ = true;
  ++builds_;
  ++version_;
}

template <class ExecSpace>
void BasicSurfaceNeighborList<ExecSpace>::save_state(CheckpointData& data) const {
  data.integers["interaction/list_built"] = {built_ ? 1 : 0};
  data.integers["interaction/rebuilds"] = {builds_};
  if (built_) data.reals["interaction/positions_at_build"] = to_flat_vector(positions_at_build_);
}

template <class ExecSpace>
void BasicSurfaceNeighborList<ExecSpace>::restore_state(const CheckpointData& data,
                                                        const PointVectors& point_positions) {
  const bool built = data.integer("interaction/list_built", 1).front() != 0;
  const int builds = static_cast<int>(data.integer("interaction/rebuilds", 1).front());
  if (built) {
    // The list as it was built: from the points' positions of that moment.
    from_flat_vector(data.real("interaction/positions_at_build", 3LL * num_points_), point_positions,
                     "interaction/positions_at_build");
    build(point_positions);
  } else {
    built_ = false;
  }
  builds_ = builds;
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicSurfaceNeighborList)

}  // namespace rouleau
