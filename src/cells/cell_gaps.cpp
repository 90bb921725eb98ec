#include "cells/cell_gaps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <stdexcept>

#include "kernels/surface_gap.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
}

CellGaps::CellGaps(const CellPopulation& population, double contact_distance)
    : population_(population), contact_distance_(contact_distance) {
  const int cells = population.num_cells();
  first_triangle_.assign(cells, 0);
  triangle_count_.assign(cells, 0);
  auto triangle_cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.triangle_cell());
  for (int t = static_cast<int>(triangle_cell.extent(0)) - 1; t >= 0; --t) {
    first_triangle_[triangle_cell(t)] = t;
    ++triangle_count_[triangle_cell(t)];
  }
  // Each cell's triangles are contiguous (the population adds cells one after another).
  for (int c = 0; c < cells; ++c)
    for (int t = first_triangle_[c]; t < first_triangle_[c] + triangle_count_[c]; ++t)
      if (triangle_cell(t) != c) throw std::logic_error("rouleau::CellGaps: a cell's surface triangles are not contiguous");
  // Each cell's triangles in patches of 8 to 16 nearby ones: halved across the widest extent
  // of their reference centroids until small enough (recursive coordinate bisection).
  auto triangles = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_triangles());
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.reference_positions());
  std::vector<std::array<double, 3>> centroid(triangles.extent(0));
  for (std::size_t t = 0; t < triangles.extent(0); ++t)
    for (int i = 0; i < 3; ++i)
      centroid[t][i] = (x(triangles(t, 0), i) + x(triangles(t, 1), i) + x(triangles(t, 2), i)) / 3.0;
  std::vector<int> order(triangles.extent(0));
  std::iota(order.begin(), order.end(), 0);
  std::vector<int> offsets{0};
  const std::function<void(int, int)> split = [&](const int begin, const int end) {
    if (end - begin <= surface_gap_patch_triangles) {
      offsets.push_back(end);
      return;
    }
    std::array<double, 3> low{INFINITY, INFINITY, INFINITY}, high{-INFINITY, -INFINITY, -INFINITY};
    for (int k = begin; k < end; ++k)
      for (int i = 0; i < 3; ++i) {
        low[i] = std::min(low[i], centroid[order[k]][i]);
        high[i] = std::max(high[i], centroid[order[k]][i]);
      }
    int axis = 0;
    for (int i = 1; i < 3; ++i)
      if (high[i] - low[i] > high[axis] - low[axis]) axis = i;
    const int middle = begin + (end - begin) / 2;
    std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                     [&](int a, int b) { return centroid[a][axis] < centroid[b][axis]; });
    split(begin, middle);
    split(middle, end);
  };
  first_patch_.assign(cells, 0);
  patch_count_.assign(cells, 0);
  for (int c = 0; c < cells; ++c) {
    first_patch_[c] = static_cast<int>(offsets.size()) - 1;
    split(first_triangle_[c], first_triangle_[c] + triangle_count_[c]);
    patch_count_[c] = static_cast<int>(offsets.size()) - 1 - first_patch_[c];
  }
  const int patches = static_cast<int>(offsets.size()) - 1;
  patch_offsets_ = Kokkos::View<int*>("rouleau::CellGaps::patch_offsets", offsets.size());
  patch_triangles_ = Kokkos::View<int*>("rouleau::CellGaps::patch_triangles", order.size());
  auto host_offsets = Kokkos::create_mirror_view(patch_offsets_);
  auto host_triangles = Kokkos::create_mirror_view(patch_triangles_);
  for (std::size_t q = 0; q < offsets.size(); ++q) host_offsets(q) = offsets[q];
  for (std::size_t k = 0; k < order.size(); ++k) host_triangles(k) = order[k];
  Kokkos::deep_copy(patch_offsets_, host_offsets);
  Kokkos::deep_copy(patch_triangles_, host_triangles);
  patch_bounds_ = Kokkos::View<double* [4]>("rouleau::CellGaps::patch_bounds", patches);
  const auto& counts = population.cell_node_count();
  const int largest = counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
  distance_ = Kokkos::View<double*>("rouleau::CellGaps::distance", largest);
}

void CellGaps::node_distances(int a, int b) const {
  using Functor = NodeToSurfaceDistanceFunctor<CellPopulation::ConstNodeVectors, Kokkos::View<const double*>,
                                               Kokkos::View<const int* [3]>, Kokkos::View<double*>>;
  Functor f{population_.positions(),
            population_.surface_area_weights(),
            population_.surface_triangles(),
            patch_offsets_,
            patch_triangles_,
            patch_bounds_,
            population_.cell_first_node()[a],
            first_patch_[b],
            patch_count_[b],
            distance_};
  Kokkos::parallel_for("rouleau::CellGaps::node_distances",
                       Kokkos::RangePolicy<ExecSpace>(0, population_.cell_node_count()[a]), f);
}

void CellGaps::locate_surfaces() const {
  if (patch_bounds_.extent(0) > 0)
    Kokkos::parallel_for("rouleau::CellGaps::patch_bounds", Kokkos::RangePolicy<ExecSpace>(0, patch_bounds_.extent(0)),
                         TrianglePatchBoundsFunctor<CellPopulation::ConstNodeVectors, Kokkos::View<const int* [3]>>{
                             population_.positions(), population_.surface_triangles(), patch_offsets_, patch_triangles_,
                             patch_bounds_});
}

std::vector<double> CellGaps::node_distances_to(int a, int b) const {
  node_distances(a, b);
  const int count = population_.cell_node_count()[a];
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), distance_);
  std::vector<double> distances(count);
  for (int k = 0; k < count; ++k) distances[k] = host(k);  // +infinity off the outer surface (the kernel's)
  return distances;
}

std::vector<CellPairGap> CellGaps::measure() const {
  ProfilingRegion region("rouleau::CellGaps::measure");
  std::vector<CellPairGap> pairs;
  locate_surfaces();
  const auto weights = population_.surface_area_weights();
  const auto distance = distance_;
  const double contact = contact_distance_;
  for (int a = 0; a < population_.num_cells(); ++a)
    for (int b = a + 1; b < population_.num_cells(); ++b) {
      CellPairGap pair{a, b, INFINITY, 0.0};
      for (const auto& [from, to] : {std::pair<int, int>{a, b}, std::pair<int, int>{b, a}}) {
        node_distances(from, to);
        const int first = population_.cell_first_node()[from], count = population_.cell_node_count()[from];
        double nearest = INFINITY, area = 0.0;
        Kokkos::parallel_reduce(
            "rouleau::CellGaps::gap", Kokkos::RangePolicy<ExecSpace>(0, count),
            KOKKOS_LAMBDA(const int k, double& smallest) { smallest = distance(k) < smallest ? distance(k) : smallest; },
            Kokkos::Min<double>(nearest));
        Kokkos::parallel_reduce(
            "rouleau::CellGaps::contact_area", Kokkos::RangePolicy<ExecSpace>(0, count),
            KOKKOS_LAMBDA(const int k, double& sum) {
              if (distance(k) < contact) sum += weights(first + k);
            },
            area);
        pair.gap = std::min(pair.gap, nearest);
        pair.contact_area += 0.5 * area;
      }
      pairs.push_back(pair);
    }
  return pairs;
}

}  // namespace rouleau
