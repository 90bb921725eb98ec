#include "coupling/rkpm_coupler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "kernels/csr_rows.hpp"
#include "kernels/rkpm.hpp"
#include "kernels/scatter_sum.hpp"
#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {


template <class ExecSpace>
BasicRkpmCoupler<ExecSpace>::BasicRkpmCoupler(const FluidMesh& mesh, double support_factor)
    : num_dof_nodes_(mesh.num_dof_nodes) {
  ProfilingRegion region("rouleau::RkpmCoupler::setup");
  // Supports: per dof node and direction, support_factor × the largest extent of the
  // elements touching it.
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto element_nodes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_nodes);
  std::vector<double> support(3 * num_dof_nodes_, 0.0);
  for (int e = 0; e < mesh.num_elements; ++e) {
    double low[3] = {1e300, 1e300, 1e300}, high[3] = {-1e300, -1e300, -1e300};
    for (int a = 0; a < mesh.nodes_per_element; ++a)
      for (int d = 0; d < 3; ++d) {
        low[d] = std::min(low[d], x(element_nodes(e, a), d));
        high[d] = std::max(high[d], x(element_nodes(e, a), d));
      }
    for (int a = 0; a < mesh.nodes_per_element; ++a) {
      const int node = mesh.dof_node_of_node[element_nodes(e, a)];
      for (int d = 0; d < 3; ++d) support[3 * node + d] = std::max(support[3 * node + d], support_factor * (high[d] - low[d]));
    }
  }
  node_position_ = Kokkos::View<double* [3]>("rouleau::RkpmCoupler::node_position", num_dof_nodes_);
  node_support_ = Kokkos::View<double* [3]>("rouleau::RkpmCoupler::node_support", num_dof_nodes_);
  auto position = Kokkos::create_mirror_view(node_position_);
  auto radius = Kokkos::create_mirror_view(node_support_);
  std::vector<char> seen(num_dof_nodes_, 0);
  for (int n = 0; n < mesh.num_nodes; ++n) {
    const int node = mesh.dof_node_of_node[n];
    if (seen[node]) continue;
    seen[node] = 1;
    for (int d = 0; d < 3; ++d) position(node, d) = x(n, d);
  }
  double smallest_support[3] = {1e300, 1e300, 1e300}, largest_support[3] = {0, 0, 0};
  for (int node = 0; node < num_dof_nodes_; ++node)
    for (int d = 0; d < 3; ++d) {
      radius(node, d) = support[3 * node + d];
      smallest_support[d] = std::min(smallest_support[d], radius(node, d));
      largest_support[d] = std::max(largest_support[d], radius(node, d));
    }
  Kokkos::deep_copy(node_position_, position);
  Kokkos::deep_copy(node_support_, radius);

  // Bins of the fluid nodes, built once, as wide as the smallest support but no narrower
  // than an eighth of the largest, each searched as deep as the supports reaching into it
  // need. On a uniform mesh that is the 3³ bins around a point's own; on a graded one a
  // point among the fine elements scans its neighbourhood, not the coarse supports' reach.
  double bin_width[3];
  for (int d = 0; d < 3; ++d) bin_width[d] = std::max(smallest_support[d], largest_support[d] / 8.0);
  const bool periodic[3] = {mesh.periodic[0], mesh.periodic[1], mesh.periodic[2]};
  node_bins_.grid = bins_tiling(mesh.lower.data(), mesh.upper.data(), periodic, bin_width, 1);
  sort_into_bins<ExecSpace>(node_position_, num_dof_nodes_, EveryPoint(), node_bins_);
  bin_depth_ = search_depths_covering(node_bins_, radius);
}

template <class ExecSpace>
void BasicRkpmCoupler<ExecSpace>::fill_rows(const Kokkos::View<const double* [3]>& points, bool count_only) {
  const RkpmSupports<typename ExecSpace::memory_space> supports{node_bins_, bin_depth_, node_position_, node_support_};
  const int corrected = rkpm_shape_functions(ExecSpace(), supports, points, active_points_, counted_points_,
                                             always_correct_, count_only, offsets_, nodes_, shape_functions_);
  if (!count_only) corrected_points_ = corrected;
}

template <class ExecSpace>
void BasicRkpmCoupler<ExecSpace>::update(const Kokkos::View<const double* [3]>& points) {
  ProfilingRegion region("rouleau::RkpmCoupler::update");
  num_points_ = static_cast<int>(points.extent(0));
  if (active_points_.extent(0) > 0 && static_cast<int>(active_points_.extent(0)) != num_points_)
    throw std::invalid_argument("rouleau::RkpmCoupler::update: " + std::to_string(num_points_) + " points, but " +
                                std::to_string(active_points_.extent(0)) + " flags of restrict_rows()");
  if (static_cast<int>(offsets_.extent(0)) != num_points_ + 1)
    offsets_ = Kokkos::View<int*>("rouleau::RkpmCoupler::offsets", num_points_ + 1);
  fill_rows(points, true);
  const int entries = counts_to_offsets<ExecSpace>("rouleau::RkpmCoupler::offsets", offsets_, num_points_);
  ensure_length(nodes_, static_cast<std::size_t>(entries), "rouleau::RkpmCoupler::nodes");
  ensure_length(shape_functions_, static_cast<std::size_t>(entries), "rouleau::RkpmCoupler::shape_functions");
  auto offsets = offsets_;
  // Active points with an empty support have left the fluid.
  const bool restricted = active_points_.extent(0) > 0;
  auto active = active_points_;
  auto outside = KOKKOS_LAMBDA(const int p) { return offsets(p + 1) == offsets(p) && (!restricted || active(p)); };
  int empty = 0;
  Kokkos::parallel_reduce(
      "rouleau::RkpmCoupler::empty_supports", Kokkos::RangePolicy<ExecSpace>(0, num_points_),
      KOKKOS_LAMBDA(const int p, int& n) { n += outside(p) ? 1 : 0; }, empty);
  if (empty > 0) {
    int first = num_points_;
    Kokkos::parallel_reduce(
        "rouleau::RkpmCoupler::first_empty_support", Kokkos::RangePolicy<ExecSpace>(0, num_points_),
        KOKKOS_LAMBDA(const int p, int& lowest) {
          if (outside(p) && p < lowest) lowest = p;
        },
        Kokkos::Min<int>(first));
    throw PointsOutsideFluidError(empty, first);
  }
  fill_rows(points, false);
}

template <class ExecSpace>
Kokkos::View<int*> BasicRkpmCoupler<ExecSpace>::support_nodes() const {
  // Persistent buffers: this runs every step of a run across ranks.
  zero_with_length(in_support_, num_dof_nodes_, "rouleau::RkpmCoupler::in_support");
  auto in_support = in_support_;
  auto offsets = offsets_;
  auto nodes = nodes_;
  int entries = 0;
  Kokkos::deep_copy(entries, Kokkos::subview(offsets_, num_points_));
  Kokkos::parallel_for(
      "rouleau::RkpmCoupler::mark_supports", Kokkos::RangePolicy<ExecSpace>(0, entries),
      KOKKOS_LAMBDA(const int k) { in_support(nodes(k)) = 1; });
  return gather_marked<ExecSpace>("rouleau::RkpmCoupler::support_nodes", num_dof_nodes_,
                                  KOKKOS_LAMBDA(const int n) { return in_support(n) != 0; }, support_nodes_);
}

template <class ExecSpace>
void BasicRkpmCoupler<ExecSpace>::interpolate(const Kokkos::View<const double*>& nodal, int stride,
                                              const PointVectors& values) const {
  ProfilingRegion region("rouleau::RkpmCoupler::interpolate");
  rkpm_interpolate(ExecSpace(), offsets_, nodes_, shape_functions_, nodal, stride, values);
}

template <class ExecSpace>
void BasicRkpmCoupler<ExecSpace>::spread(const PointVectors& forces, const Kokkos::View<double*>& nodal,
                                         int stride) const {
  ProfilingRegion region("rouleau::RkpmCoupler::spread");
  const std::size_t size = nodal.extent(0);
  if (spread_sum_.extent(0) != size) {
    spread_sum_ = Kokkos::View<double*>("rouleau::RkpmCoupler::spread_sum", size);
    spread_scatter_ = Scatter("rouleau::RkpmCoupler::spread_scatter", size);
  }
  spread_scatter_.reset();
  rkpm_spread(ExecSpace(), offsets_, nodes_, shape_functions_, forces, spread_scatter_, stride);
  gather_into(spread_sum_, spread_scatter_);
  auto sum = spread_sum_;
  Kokkos::parallel_for(
      "rouleau::RkpmCoupler::spread_add", Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(size)),
      KOKKOS_LAMBDA(const int i) { nodal(i) += sum(i); });
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicRkpmCoupler)

}  // namespace rouleau
