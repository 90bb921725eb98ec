#include "distributed/distributed_fluid_operator.hpp"

#include <stdexcept>
#include <string>

#include "util/view_transfer.hpp"
#include <unordered_map>

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;

// y_d = x_d on the constrained unknowns
void identity_rows(const Kokkos::View<int*>& dofs, const Kokkos::View<const double*>& x, const Kokkos::View<double*>& y) {
  Kokkos::parallel_for(
      "rouleau::DistributedStokesOperator::dirichlet_rows", Kokkos::RangePolicy<ExecSpace>(0, dofs.extent(0)),
      KOKKOS_LAMBDA(const int k) { y(dofs(k)) = x(dofs(k)); });
}

// Row (d mod 4) of node ⌊d/4⌋'s block becomes the identity's.
void identity_block_rows(const Kokkos::View<int*>& dofs, const Vector& blocks) {
  Kokkos::parallel_for(
      "rouleau::DistributedBlockJacobi::dirichlet_rows", Kokkos::RangePolicy<ExecSpace>(0, dofs.extent(0)),
      KOKKOS_LAMBDA(const int k) {
        const int node = dofs(k) / 4, row = dofs(k) % 4;
        for (int c = 0; c < 4; ++c) blocks(16 * node + 4 * row + c) = c == row ? 1.0 : 0.0;
      });
}
}  // namespace

void require_node_sums(const FluidOperator& local, const char* who) {
  if (!local.has_node_sums())
    throw std::invalid_argument(std::string("rouleau::") + who +
                                ": the rank's operator does not complete its element sums across ranks "
                                "(FluidOperator::set_node_sums with a NodeSums)");
}

std::vector<int> owned_local_unknowns(const ElementPartition& partition, const std::vector<int>& global_unknowns) {
  std::unordered_map<int, int> local_node;
  for (int l = 0; l < partition.num_owned_nodes; ++l) local_node[partition.global_node[l]] = l;
  std::vector<int> local;
  for (const int g : global_unknowns) {
    const auto found = local_node.find(g / 4);
    if (found != local_node.end()) local.push_back(4 * found->second + g % 4);
  }
  return local;
}

DistributedStokesOperator::DistributedStokesOperator(const FluidOperator& local, const ElementPartition& partition,
                                                     const std::vector<int>& dirichlet)
    : local_(local),
      owned_(4 * partition.num_owned_nodes),
      dirichlet_(device_copy(dirichlet, "rouleau::DistributedStokesOperator::dirichlet")),
      local_x_("rouleau::DistributedStokesOperator::local_x", 4 * partition.num_local_nodes()),
      local_y_("rouleau::DistributedStokesOperator::local_y", 4 * partition.num_local_nodes()) {
  require_node_sums(local, "DistributedStokesOperator");
}

void DistributedStokesOperator::owned_part(const Kokkos::View<const double*>& local,
                                           const Kokkos::View<double*>& owned) const {
  Kokkos::deep_copy(owned, Kokkos::subview(local, Kokkos::make_pair(0, owned_)));
}

void DistributedStokesOperator::apply(const Kokkos::View<const double*>& x, const Kokkos::View<double*>& y) const {
  // y = Σ_ranks Σ_e K_e x (the operator's node sums), then y_d = x_d
  Kokkos::deep_copy(Kokkos::subview(local_x_, Kokkos::make_pair(0, owned_)), x);
  local_.start_filling_copies(local_x_);  // completed inside the element loop
  local_.linear_action(local_x_, local_y_);
  owned_part(local_y_, y);
  identity_rows(dirichlet_, x, y);
}

DistributedBlockJacobi::DistributedBlockJacobi(const Communicator& communicator, const ElementPartition& partition,
                                               const std::vector<int>& dirichlet)
    : communicator_(communicator),
      owned_nodes_(partition.num_owned_nodes),
      dirichlet_(device_copy(dirichlet, "rouleau::DistributedBlockJacobi::dirichlet")),
      local_blocks_("rouleau::DistributedBlockJacobi::local_blocks", 16 * partition.num_local_nodes()),
      jacobi_(partition.num_owned_nodes) {}

void DistributedBlockJacobi::factor(const FluidOperator& local, const ConstVector& state) {
  require_node_sums(local, "DistributedBlockJacobi");
  local.diagonal_blocks(state, local_blocks_);  // completed across ranks
  identity_block_rows(dirichlet_, local_blocks_);
  const long long singular =
      jacobi_.factor(Kokkos::subview(local_blocks_, Kokkos::make_pair(0, 16 * owned_nodes_)));
  singular_blocks_ = communicator_.sum(singular);
}

void DistributedBlockJacobi::apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const {
  jacobi_.apply(r, z);
}

}  // namespace rouleau
