#include "distributed/fluid_distribution.hpp"

#include <KokkosBlas1_dot.hpp>
#include <spdlog/spdlog.h>
#include <algorithm>
#include <cmath>

#include "distributed/additive_schwarz.hpp"
#include "distributed/distributed_fluid_operator.hpp"
#include "distributed/local_mesh.hpp"
#include "kernels/csr_rows.hpp"
#include "util/view_transfer.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
using Vector = FluidDistribution::Vector;
using ConstVector = FluidDistribution::ConstVector;

// global(4·g(i) + c) = local(4 i + c) for the first `nodes` local nodes, the rest zero.
void place_owned(const Kokkos::View<int*>& global_node, const int nodes, const ConstVector& local, const Vector& global) {
  Kokkos::deep_copy(global, 0.0);
  Kokkos::parallel_for(
      "rouleau::FluidDistribution::place_owned", Kokkos::RangePolicy<ExecSpace>(0, nodes), KOKKOS_LAMBDA(const int i) {
        for (int c = 0; c < fluid_unknowns_per_node; ++c)
          global(fluid_unknowns_per_node * global_node(i) + c) = local(fluid_unknowns_per_node * i + c);
      });
}

// local(4 i + c) = global(4·g(i) + c) at every local node
void take_local(const Kokkos::View<int*>& global_node, const ConstVector& global, const Vector& local) {
  Kokkos::parallel_for(
      "rouleau::FluidDistribution::localize", Kokkos::RangePolicy<ExecSpace>(0, global_node.extent(0)),
      KOKKOS_LAMBDA(const int i) {
        for (int c = 0; c < fluid_unknowns_per_node; ++c)
          local(fluid_unknowns_per_node * i + c) = global(fluid_unknowns_per_node * global_node(i) + c);
      });
}
// buffer(4k + c) = local(4 l + c) where this rank owns node g = nodes(k) as l, else 0
void gather_owned_at(const Kokkos::View<int*>& owned_local, const Kokkos::View<const int*>& nodes,
                     const ConstVector& local, const Vector& buffer) {
  Kokkos::parallel_for(
      "rouleau::FluidDistribution::gather_owned_at", Kokkos::RangePolicy<ExecSpace>(0, nodes.extent(0)),
      KOKKOS_LAMBDA(const int k) {
        const int l = owned_local(nodes(k));
        for (int c = 0; c < fluid_unknowns_per_node; ++c)
          buffer(fluid_unknowns_per_node * k + c) = l >= 0 ? local(fluid_unknowns_per_node * l + c) : 0.0;
      });
}

// buffer(4k + c) = global(4 nodes(k) + c)
void gather_at(const Kokkos::View<const int*>& nodes, const ConstVector& global, const Vector& buffer) {
  Kokkos::parallel_for(
      "rouleau::FluidDistribution::gather_at", Kokkos::RangePolicy<ExecSpace>(0, nodes.extent(0)),
      KOKKOS_LAMBDA(const int k) {
        for (int c = 0; c < fluid_unknowns_per_node; ++c)
          buffer(fluid_unknowns_per_node * k + c) = global(fluid_unknowns_per_node * nodes(k) + c);
      });
}

// global(4 nodes(k) + c) = buffer(4k + c)
void scatter_to_nodes(const Kokkos::View<const int*>& nodes, const ConstVector& buffer, const Vector& global) {
  Kokkos::parallel_for(
      "rouleau::FluidDistribution::scatter_to_nodes", Kokkos::RangePolicy<ExecSpace>(0, nodes.extent(0)),
      KOKKOS_LAMBDA(const int k) {
        for (int c = 0; c < fluid_unknowns_per_node; ++c)
          global(fluid_unknowns_per_node * nodes(k) + c) = buffer(fluid_unknowns_per_node * k + c);
      });
}

// global dof node → local dof node, or −1 where the rank holds none
std::vector<int> local_of_global_of(const ElementPartition& partition) {
  std::vector<int> local(partition.num_global_nodes, -1);
  for (int i = 0; i < partition.num_local_nodes(); ++i) local[partition.global_node[i]] = i;
  return local;
}

// The largest distance between two nodes of an element: the nearest dof node to a point
// inside the fluid is within it.
double largest_element_diameter(const FluidMesh& mesh) {
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto element_nodes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_nodes);
  double diameter2 = 0.0;
  for (int e = 0; e < mesh.num_elements; ++e)
    for (int a = 0; a < mesh.nodes_per_element; ++a)
      for (int b = a + 1; b < mesh.nodes_per_element; ++b) {
        double d2 = 0.0;
        for (int d = 0; d < 3; ++d) {
          const double offset = coordinates(element_nodes(e, a), d) - coordinates(element_nodes(e, b), d);
          d2 += offset * offset;
        }
        diameter2 = std::max(diameter2, d2);
      }
  return std::sqrt(diameter2);
}

// The geometric nodes of the dof nodes this rank owns (a periodic dof node's every image).
Kokkos::View<double* [3], Kokkos::HostSpace> owned_geometric_nodes(const FluidMesh& mesh,
                                                                   const std::vector<int>& local_of_global,
                                                                   const int owned_nodes) {
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  std::vector<int> owned;
  for (int g = 0; g < mesh.num_nodes; ++g) {
    const int local = local_of_global[mesh.dof_node_of_node[g]];
    if (local >= 0 && local < owned_nodes) owned.push_back(g);
  }
  Kokkos::View<double* [3], Kokkos::HostSpace> positions("rouleau::FluidDistribution::owned_node_positions",
                                                         owned.size());
  for (std::size_t i = 0; i < owned.size(); ++i)
    for (int d = 0; d < 3; ++d) positions(i, d) = coordinates(owned[i], d);
  return positions;
}
}  // namespace

FluidDistribution::FluidDistribution(const Communicator& communicator, const FluidMesh& global_mesh)
    : communicator_(communicator),
      partition_(partition_fluid_mesh(global_mesh, communicator.rank(), communicator.size())),
      local_mesh_(make_local_mesh(global_mesh, partition_)),
      halo_(communicator_, partition_, fluid_unknowns_per_node),
      node_sums_(communicator_, partition_),
      local_of_global_(local_of_global_of(partition_)),
      owned_node_positions_(owned_geometric_nodes(global_mesh, local_of_global_, partition_.num_owned_nodes)),
      largest_element_diameter_(largest_element_diameter(global_mesh)),
      global_node_(device_copy(partition_.global_node, "rouleau::FluidDistribution::global_node")) {
  const bool periodic[3] = {global_mesh.periodic[0], global_mesh.periodic[1], global_mesh.periodic[2]};
  const double width[3] = {largest_element_diameter_, largest_element_diameter_, largest_element_diameter_};
  owned_node_bins_.grid = bins_tiling(global_mesh.lower.data(), global_mesh.upper.data(), periodic, width, 1);
  sort_into_bins<Kokkos::DefaultHostExecutionSpace>(owned_node_positions_,
                                                    static_cast<int>(owned_node_positions_.extent(0)),
                                                    EveryPoint(), owned_node_bins_);
  std::vector<int> owned_local(partition_.num_global_nodes, -1);
  for (int i = 0; i < partition_.num_owned_nodes; ++i) owned_local[partition_.global_node[i]] = i;
  owned_local_ = device_copy(owned_local, "rouleau::FluidDistribution::owned_local");
}

void FluidDistribution::sum_over_ranks(const Vector& values) const {
  if (communicator_.size() == 1) return;
  // MPI sees host memory (as NodeHalo's exchanges do).
  if (host_buffer_.extent(0) < values.extent(0))
    host_buffer_ = Kokkos::View<double*, Kokkos::HostSpace>("rouleau::FluidDistribution::host_buffer", values.extent(0));
  const auto host = Kokkos::subview(host_buffer_, std::make_pair(std::size_t(0), values.extent(0)));
  Kokkos::deep_copy(host, values);
  communicator_.sum(host.data(), static_cast<int>(host.extent(0)));
  Kokkos::deep_copy(values, host);
}

double FluidDistribution::dot(const ConstVector& x, const ConstVector& y) const {
  const auto owned = std::make_pair(0, num_owned_unknowns());
  return communicator_.sum(KokkosBlas::dot(Kokkos::subview(x, owned), Kokkos::subview(y, owned)));
}

double FluidDistribution::norm(const ConstVector& x) const { return std::sqrt(dot(x, x)); }

void FluidDistribution::replicate(const ConstVector& local, const Vector& global,
                                  const Kokkos::View<const int*>& nodes) const {
  if (nodes.extent(0) > 0) {
    replicate_at(local, global, nodes);
    return;
  }
  place_owned(global_node_, partition_.num_owned_nodes, local, global);
  sum_over_ranks(global);
}

FluidDistribution::Vector FluidDistribution::node_buffer(const int nodes) const {
  const int size = fluid_unknowns_per_node * nodes;
  if (static_cast<int>(node_buffer_.extent(0)) < size)
    node_buffer_ = Vector("rouleau::FluidDistribution::node_buffer", size + size / 5);
  return Kokkos::subview(node_buffer_, std::make_pair(0, size));
}

void FluidDistribution::replicate_at(const ConstVector& local, const Vector& global,
                                     const Kokkos::View<const int*>& nodes) const {
  const Vector buffer = node_buffer(static_cast<int>(nodes.extent(0)));
  gather_owned_at(owned_local_, nodes, local, buffer);
  sum_over_ranks(buffer);
  scatter_to_nodes(nodes, buffer, global);
}

void FluidDistribution::sum_at_nodes(const Vector& global, const Kokkos::View<const int*>& nodes) const {
  const Vector buffer = node_buffer(static_cast<int>(nodes.extent(0)));
  gather_at(nodes, global, buffer);
  sum_over_ranks(buffer);
  scatter_to_nodes(nodes, buffer, global);
}

void FluidDistribution::localize(const ConstVector& global, const Vector& local) const {
  take_local(global_node_, global, local);
}

Kokkos::View<const int*> FluidDistribution::nodes_of_any_rank(const Kokkos::View<const int*>& nodes) const {
  const int global_nodes = partition_.num_global_nodes;
  const int words = (global_nodes + 31) / 32;
  if (static_cast<int>(node_bits_.extent(0)) != words) {
    node_bits_ = Kokkos::View<unsigned*>("rouleau::FluidDistribution::node_bits", words);
    host_node_bits_ = Kokkos::create_mirror_view(Kokkos::HostSpace(), node_bits_);
  } else {
    Kokkos::deep_copy(node_bits_, 0u);
  }
  auto bits = node_bits_;
  Kokkos::parallel_for(
      "rouleau::FluidDistribution::mark_nodes", Kokkos::RangePolicy<ExecSpace>(0, nodes.extent(0)),
      KOKKOS_LAMBDA(const int k) { Kokkos::atomic_fetch_or(&bits(nodes(k) / 32), 1u << (nodes(k) % 32)); });
  Kokkos::deep_copy(host_node_bits_, node_bits_);
  communicator_.bitwise_or(host_node_bits_.data(), words);
  Kokkos::deep_copy(node_bits_, host_node_bits_);
  return gather_marked<ExecSpace>(
      "rouleau::FluidDistribution::nodes_of_any_rank", global_nodes,
      KOKKOS_LAMBDA(const int n) { return ((bits(n / 32) >> (n % 32)) & 1u) != 0; }, nodes_of_any_rank_);
}

std::vector<int> FluidDistribution::rank_holding(const std::vector<std::array<double, 3>>& points) const {
  std::vector<double> distance(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    distance[i] = nearest_distance(owned_node_bins_, owned_node_positions_, points[i].data(), largest_element_diameter_);
  return communicator_.rank_of_smallest(distance);
}

std::unique_ptr<FluidPreconditioner> FluidDistribution::make_preconditioner(
    const SolverConfig& solver, const std::vector<int>& owned_dirichlet) const {
  switch (solver.preconditioner) {
    case PreconditionerType::block_jacobi:
      return std::make_unique<DistributedBlockJacobi>(communicator_, partition_, owned_dirichlet);
    case PreconditionerType::ilu0:
      return std::make_unique<AdditiveSchwarz>(communicator_, partition_, local_mesh_, owned_dirichlet,
                                               SubdomainSolver::ilu0);
    case PreconditionerType::automatic:
    case PreconditionerType::multigrid:
      return std::make_unique<AdditiveSchwarz>(communicator_, partition_, local_mesh_, owned_dirichlet,
                                               SubdomainSolver::multigrid, multigrid_settings(solver));
    case PreconditionerType::fast_diagonalization:
      // Its transforms span the whole box: across ranks, each subdomain's multigrid instead.
      if (communicator_.rank() == 0)
        spdlog::warn("solver.preconditioner = \"fast_diagonalization\" runs on one rank; across {} ranks the "
                     "subdomains' multigrid is used instead",
                     communicator_.size());
      return std::make_unique<AdditiveSchwarz>(communicator_, partition_, local_mesh_, owned_dirichlet,
                                               SubdomainSolver::multigrid, multigrid_settings(solver));
    case PreconditionerType::none: break;
  }
  SolverConfig none = solver;
  none.preconditioner = PreconditionerType::none;
  return make_fluid_preconditioner(none, local_mesh_);
}

}  // namespace rouleau
