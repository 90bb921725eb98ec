#include "coupling/rkpm_coupler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

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
  double largest_support[3] = {0, 0, 0};
  for (int node = 0; node < num_dof_nodes_; ++node)
    for (int d = 0; d < 3; ++d) {
      radius(node, d) = support[3 * node + d];
      largest_support[d] = std::max(largest_support[d], radius(node, d));
    }
  Kokkos::deep_copy(node_position_, position);
  Kokkos::deep_copy(node_support_, radius);

  // Bins of the fluid nodes, built once: no narrower than the largest support, so a
  // point's support lies in the 3³ bins around its own.
  RkpmSupportSearch& search = search_;
  for (int d = 0; d < 3; ++d) {
    search.lower[d] = mesh.lower[d];
    search.length[d] = mesh.upper[d] - mesh.lower[d];
    search.periodic[d] = mesh.periodic[d] ? 1 : 0;
    search.bins[d] = std::max(1, static_cast<int>(std::floor(search.length[d] / largest_support[d])));
    search.bin_size[d] = search.length[d] / search.bins[d];
  }
  const int n_bins = search.bins[0] * search.bins[1] * search.bins[2];
  std::vector<std::vector<int>> members(n_bins);
  for (int node = 0; node < num_dof_nodes_; ++node) {
    int b[3];
    for (int d = 0; d < 3; ++d) b[d] = search.bin_coordinate(position(node, d), d);
    members[(b[2] * search.bins[1] + b[1]) * search.bins[0] + b[0]].push_back(node);
  }
  bin_offsets_ = Kokkos::View<int*>("rouleau::RkpmCoupler::bin_offsets", n_bins + 1);
  binned_nodes_ = Kokkos::View<int*>("rouleau::RkpmCoupler::binned_nodes", num_dof_nodes_);
  auto h_offsets = Kokkos::create_mirror_view(bin_offsets_);
  auto h_binned = Kokkos::create_mirror_view(binned_nodes_);
  int k = 0;
  for (int b = 0; b < n_bins; ++b) {
    h_offsets(b) = k;
    for (const int node : members[b]) h_binned(k++) = node;
  }
  h_offsets(n_bins) = k;
  Kokkos::deep_copy(bin_offsets_, h_offsets);
  Kokkos::deep_copy(binned_nodes_, h_binned);
}

template <class ExecSpace>
void BasicRkpmCoupler<ExecSpace>::fill_rows(const Kokkos::View<const double* [3]>& points, bool count_only) {
  const RkpmSupportSearch search = search_;
  auto node_position = node_position_;
  auto node_support = node_support_;
  auto bin_offsets = bin_offsets_;
  auto binned = binned_nodes_;
  auto offsets = offsets_;
  auto nodes = nodes_;
  auto phi = shape_functions_;
  const bool always_correct = always_correct_;
  const bool restricted = active_points_.extent(0) > 0;
  auto active = active_points_;
  const bool counting_some = counted_points_.extent(0) > 0;
  auto counted = counted_points_;
  int corrected = 0;
  Kokkos::parallel_reduce(
      "rouleau::RkpmCoupler::shape_functions", Kokkos::RangePolicy<ExecSpace>(0, num_points_),
      KOKKOS_LAMBDA(const int p, int& corrected_count) {
        if (restricted && !active(p)) {  // an empty row (restrict_rows)
          if (count_only) offsets(p + 1) = 0;
          return;
        }
        const double x[3] = {points(p, 0), points(p, 1), points(p, 2)};
        int home[3];
        for (int d = 0; d < 3; ++d) home[d] = search.bin_coordinate(x[d], d);
        int count = 0;
        const int first = count_only ? 0 : offsets(p);
        // M = Σ H H^T w with H = (1, y), y = x_J − x
        double m[4][4] = {{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
        // The 3³ bins around the point's (fewer when a direction has fewer bins).
        int span[3];
        for (int d = 0; d < 3; ++d) span[d] = search.bins[d] < 3 ? search.bins[d] : 3;
        for (int iz = 0; iz < span[2]; ++iz)
          for (int iy = 0; iy < span[1]; ++iy)
            for (int ix = 0; ix < span[0]; ++ix) {
              const int shift[3] = {ix, iy, iz};
              int b[3];
              bool inside = true;
              for (int d = 0; d < 3; ++d) {
                b[d] = search.bins[d] < 3 ? shift[d] : home[d] - 1 + shift[d];
                if (search.periodic[d]) b[d] = (b[d] % search.bins[d] + search.bins[d]) % search.bins[d];
                else if (b[d] < 0 || b[d] >= search.bins[d]) inside = false;
              }
              if (!inside) continue;
              const int bin = (b[2] * search.bins[1] + b[1]) * search.bins[0] + b[0];
              for (int k = bin_offsets(bin); k < bin_offsets(bin + 1); ++k) {
                const int node = binned(k);
                double y[3], w = 1.0;
                for (int d = 0; d < 3; ++d) {
                  y[d] = search.offset(node_position(node, d), x[d], d);
                  w *= cubic_bspline_window(y[d] / node_support(node, d));
                }
                if (!(w > 0.0)) continue;
                if (!count_only) {
                  nodes(first + count) = node;
                  phi(first + count) = w;
                  const double h[4] = {1.0, y[0], y[1], y[2]};
                  for (int i = 0; i < 4; ++i)
                    for (int j = 0; j < 4; ++j) m[i][j] += h[i] * h[j] * w;
                }
                ++count;
              }
            }
        if (count_only) {
          offsets(p + 1) = count;
          return;
        }
        // Skip the correction where the window alone is a partition of unity with zero
        // first moments (it then reproduces linear fields as it is).
        const double scale = m[0][0] > 0 ? 1.0 : 0.0;
        const double first_moment = fabs(m[0][1]) + fabs(m[0][2]) + fabs(m[0][3]);
        const double support_scale = node_support(nodes(first), 0) + node_support(nodes(first), 1) +
                                     node_support(nodes(first), 2);
        const bool plain_reproduces =
            scale > 0 && fabs(m[0][0] - 1.0) < 1e-12 && first_moment < 1e-12 * support_scale;
        if (plain_reproduces && !always_correct) return;
        double c[4] = {0, 0, 0, 0};
        if (!solve_moment_system(m, c)) {
          for (int k = first; k < first + count; ++k) phi(k) = NAN;
          return;
        }
        // Φ_J = H(0)^T M⁻¹ H(y_J) w_J = (c · H(y_J)) w_J with M c = H(0)
        for (int k = first; k < first + count; ++k) {
          const int node = nodes(k);
          double y[3];
          for (int d = 0; d < 3; ++d) y[d] = search.offset(node_position(node, d), x[d], d);
          phi(k) *= c[0] + c[1] * y[0] + c[2] * y[1] + c[3] * y[2];
        }
        if (!counting_some || counted(p)) ++corrected_count;
      },
      corrected);
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
  Kokkos::deep_copy(offsets_, 0);
  fill_rows(points, true);
  auto offsets = offsets_;
  int entries = 0;
  Kokkos::parallel_scan(
      "rouleau::RkpmCoupler::offsets", Kokkos::RangePolicy<ExecSpace>(0, num_points_ + 1),
      KOKKOS_LAMBDA(const int i, int& sum, const bool final) {
        sum += offsets(i);
        if (final) offsets(i) = sum;
      },
      entries);
  if (static_cast<int>(nodes_.extent(0)) < entries) {
    nodes_ = Kokkos::View<int*>("rouleau::RkpmCoupler::nodes", entries + entries / 5);
    shape_functions_ = Kokkos::View<double*>("rouleau::RkpmCoupler::shape_functions", entries + entries / 5);
  }
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
  if (static_cast<int>(in_support_.extent(0)) != num_dof_nodes_)
    in_support_ = Kokkos::View<int*>("rouleau::RkpmCoupler::in_support", num_dof_nodes_);
  else
    Kokkos::deep_copy(in_support_, 0);
  auto in_support = in_support_;
  auto offsets = offsets_;
  auto nodes = nodes_;
  int entries = 0;
  Kokkos::deep_copy(entries, Kokkos::subview(offsets_, num_points_));
  Kokkos::parallel_for(
      "rouleau::RkpmCoupler::mark_supports", Kokkos::RangePolicy<ExecSpace>(0, entries),
      KOKKOS_LAMBDA(const int k) { in_support(nodes(k)) = 1; });
  // The marked nodes, compacted in order: position = the number marked before.
  int count = 0;
  Kokkos::parallel_reduce(
      "rouleau::RkpmCoupler::count_supports", Kokkos::RangePolicy<ExecSpace>(0, num_dof_nodes_),
      KOKKOS_LAMBDA(const int n, int& sum) { sum += in_support(n); }, count);
  if (static_cast<int>(support_nodes_.extent(0)) < count)
    support_nodes_ = Kokkos::View<int*>("rouleau::RkpmCoupler::support_nodes", count + count / 5);
  const auto support = Kokkos::subview(support_nodes_, std::make_pair(0, count));
  Kokkos::parallel_scan(
      "rouleau::RkpmCoupler::compact_supports", Kokkos::RangePolicy<ExecSpace>(0, num_dof_nodes_),
      KOKKOS_LAMBDA(const int n, int& before, const bool final) {
        if (final && in_support(n)) support(before) = n;
        before += in_support(n);
      });
  return support;
}

template <class ExecSpace>
void BasicRkpmCoupler<ExecSpace>::interpolate(const Kokkos::View<const double*>& nodal, int stride,
                                              const PointVectors& values) const {
  ProfilingRegion region("rouleau::RkpmCoupler::interpolate");
  auto offsets = offsets_;
  auto nodes = nodes_;
  auto phi = shape_functions_;
  // u(x_p) = Σ_J Φ_J(x_p) u_J: one thread per point, a pure gather
  Kokkos::parallel_for(
      "rouleau::RkpmCoupler::interpolate", Kokkos::RangePolicy<ExecSpace>(0, num_points_),
      KOKKOS_LAMBDA(const int p) {
        double u[3] = {0, 0, 0};
        for (int k = offsets(p); k < offsets(p + 1); ++k)
          for (int c = 0; c < 3; ++c) u[c] += phi(k) * nodal(stride * nodes(k) + c);
        for (int c = 0; c < 3; ++c) values(p, c) = u[c];
      });
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
  auto scatter = spread_scatter_;
  auto offsets = offsets_;
  auto nodes = nodes_;
  auto phi = shape_functions_;
  // F_J += Σ_p Φ_J(x_p) F_p: the transpose of interpolate
  Kokkos::parallel_for(
      "rouleau::RkpmCoupler::spread", Kokkos::RangePolicy<ExecSpace>(0, num_points_), KOKKOS_LAMBDA(const int p) {
        auto access = scatter.access();
        for (int k = offsets(p); k < offsets(p + 1); ++k)
          for (int c = 0; c < 3; ++c) access(stride * nodes(k) + c) += phi(k) * forces(p, c);
      });
  gather_into(spread_sum_, spread_scatter_);
  auto sum = spread_sum_;
  Kokkos::parallel_for(
      "rouleau::RkpmCoupler::spread_add", Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(size)),
      KOKKOS_LAMBDA(const int i) { nodal(i) += sum(i); });
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicRkpmCoupler)

}  // namespace rouleau
