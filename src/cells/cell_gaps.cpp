#include "cells/cell_gaps.hpp"

#include <algorithm>
#include <cmath>
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
  const auto& counts = population.cell_node_count();
  const int largest = counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
  distance_ = Kokkos::View<double*>("rouleau::CellGaps::distance", largest);
}

void CellGaps::node_distances(int a, int b) const {
  using Functor = NodeToSurfaceDistanceFunctor<CellPopulation::ConstNodeVectors, Kokkos::View<const double*>,
                                               Kokkos::View<const int* [3]>, Kokkos::View<double*>>;
  Functor f{population_.positions(), population_.surface_area_weights(), population_.surface_triangles(),
            population_.cell_first_node()[a], first_triangle_[b], triangle_count_[b], distance_};
  Kokkos::parallel_for("rouleau::CellGaps::node_distances",
                       Kokkos::RangePolicy<ExecSpace>(0, population_.cell_node_count()[a]), f);
}

std::vector<CellPairGap> CellGaps::measure() const {
  ProfilingRegion region("rouleau::CellGaps::measure");
  std::vector<CellPairGap> pairs;
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
