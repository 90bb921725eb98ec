#include "distributed/node_sums.hpp"

#include <stdexcept>
#include <string>

namespace rouleau {

NodeSums::NodeSums(const Communicator& communicator, const ElementPartition& partition)
    : communicator_(communicator), partition_(partition) {}

void NodeSums::operator()(const Kokkos::View<double*>& values, int components) const {
  if (static_cast<long>(values.extent(0)) != static_cast<long>(components) * partition_.num_local_nodes())
    throw std::logic_error("rouleau::NodeSums: a vector of " + std::to_string(values.extent(0)) + " entries is not " +
                           std::to_string(components) + " per local node");
  std::unique_ptr<NodeHalo>& halo = halos_[components];
  if (!halo) halo = std::make_unique<NodeHalo>(communicator_, partition_, components);
  halo->sum_into_owners(values);
}

}  // namespace rouleau
