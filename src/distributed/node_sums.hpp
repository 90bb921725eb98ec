#pragma once
// The element sums of a rank's mesh completed across ranks, for
// FluidOperator::set_node_sums (issue 10): after an element loop, each shared node's
// partial sums are added at its owner and the total goes back to the copies
// (NodeHalo::sum_into_owners), so every local entry, owned or copy, holds what one rank
// with the whole mesh would have. One NodeHalo per number of components per node (1, 4,
// 9, 16), made on first use.
#include <Kokkos_Core.hpp>
#include <map>
#include <memory>

#include "distributed/node_halo.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"

namespace rouleau {

class NodeSums {
 public:
  // `partition` must outlive this.
  NodeSums(const Communicator& communicator, const ElementPartition& partition);
  void operator()(const Kokkos::View<double*>& values, int components) const;

 private:
  Communicator communicator_;
  const ElementPartition& partition_;
  mutable std::map<int, std::unique_ptr<NodeHalo>> halos_;  // by components per node
};

}  // namespace rouleau
