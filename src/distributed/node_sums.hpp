#pragma once
// The element sums of a rank's mesh completed across ranks, for
// FluidOperator::set_node_sums (the protocol in fluid/element_sum_exchange.hpp):
// each shared node's partial sums are added at its owner (NodeHalo::add_copies_to_owners)
// and the total goes back to the copies (NodeHalo::update_copies), so every local entry,
// owned or copy, holds what one rank with the whole mesh would have. With overlap on, the
// two exchanges, and the ghost exchange of an action's input (start_copies), travel while
// the rank's interior elements are summed; off, each exchange completes where it is posted.
// On by default where the element loops run on a GPU: a loop's kernels run while the host
// waits in MPI, and the one extra pass over the sums (the interior's, added at the end)
// touches one atomic buffer. Off by default on CPU threads: there the extra pass runs over
// every thread's copy of the sums, and between two ranks of this project's machine the
// overlapped action ran 0.94-1.07x the baseline's time (paired medians, no gain), the
// exchanges it would hide being 0.3-0.5 % of it (bench/mpi.md, "A GMRES iteration
// on 1 and 2 ranks"); set_overlap(true) where a network's latency outweighs that. One NodeHalo per
// number of components per node (1, 4, 9, 16), made on first use.
#include <Kokkos_Core.hpp>
#include <map>
#include <memory>

#include "distributed/node_halo.hpp"
#include "fluid/element_sum_exchange.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"

namespace rouleau {

class NodeSums final : public ElementSumExchange {
 public:
  // `partition` must outlive this.
  NodeSums(const Communicator& communicator, const ElementPartition& partition);
  int boundary_elements() const override { return partition_.num_boundary_elements; }
  bool overlaps() const override { return overlap_; }
  void set_overlap(bool overlap) { overlap_ = overlap; }
  void complete(const Kokkos::View<double*>& values, int components) const override;
  void start(const Kokkos::View<double*>& values, int components) const override;
  void advance(const Kokkos::View<double*>& values, int components) const override;
  void finish(const Kokkos::View<double*>& values, int components) const override;
  void start_copies(const Kokkos::View<double*>& input) const override;
  bool copies_in_flight() const override { return input_in_flight_; }
  void await_copies() const override;

 private:
  const NodeHalo& halo(const Kokkos::View<double*>& values, int components) const;
  Communicator communicator_;
  const ElementPartition& partition_;
  bool overlap_;
  mutable std::map<int, std::unique_ptr<NodeHalo>> halos_;  // by components per node
  mutable Kokkos::View<double*> input_;                    // the input whose copies travel
  mutable bool input_in_flight_ = false;
};

}  // namespace rouleau
