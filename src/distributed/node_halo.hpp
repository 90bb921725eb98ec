#pragma once
// The exchange of shared dof nodes' values between ranks, for node-interleaved
// vectors of `components` entries per node (4 for the fluid's u, v, w, p) on the local
// dof nodes of an ElementPartition (parallel/element_partition.hpp).
//
// update_copies():   every copy takes its owner's value (before an operator reads them);
// add_copies_to_owners(): the owner adds the copies' partial sums to its own, in ascending
//                    rank order (after an element loop, when only owned entries are read
//                    next); the copies keep their partial sums;
// sum_into_owners(): the same, and the totals go back to the copies.
// dot():             Σ x·y over the owned entries of all ranks (each unknown counted once).
// The exchanges also come in two steps, start_*() and finish(), so that work on entries
// the exchange neither reads nor writes (the interior nodes) can run while the messages
// travel (NodeSums: the interior elements' loops).
// Values are packed on the device, staged through host buffers for MPI, and unpacked on
// the device; in a build without MPI (or on one rank) there is nothing to exchange.
#include <Kokkos_Core.hpp>
#include <vector>

#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"

namespace rouleau {

class NodeHalo {
 public:
  using Vector = Kokkos::View<double*>;
  using ConstVector = Kokkos::View<const double*>;

  NodeHalo(const Communicator& communicator, const ElementPartition& partition, int components);

  void update_copies(const Vector& values) const;
  void add_copies_to_owners(const Vector& values) const;
  void sum_into_owners(const Vector& values) const;
  double dot(const ConstVector& x, const ConstVector& y) const;

  // update_copies() and add_copies_to_owners() in two steps: start_*() packs the outgoing
  // values and posts the messages; finish() waits for them and unpacks. One exchange is in
  // flight at a time (std::logic_error otherwise), and the shared entries of `values` must
  // not change in between.
  void start_update_copies(const Vector& values) const;
  void start_add_copies_to_owners(const Vector& values) const;
  void finish(const Vector& values) const;

  int num_owned_entries() const { return owned_entries_; }
  // Values sent per update_copies() (summed over the neighbours) — the halo's size.
  long long values_per_update() const;

 private:
  struct Link {
    int rank;
    Kokkos::View<int*> owned_shared, copies;      // local dof nodes (device)
    Vector owned_buffer, copy_buffer;             // staging, components per node
  };
  // owners → copies: the copies take the owners' values; copies → owners: the owners add
  // the copies' values (partial sums) to theirs.
  enum class Direction { owners_to_copies, copies_to_owners };
  void start(Direction direction, const Vector& values) const;
  Communicator communicator_;
  int components_;
  int owned_entries_;
  std::vector<Link> links_;
  std::vector<int> ranks_;
  mutable std::vector<std::vector<double>> send_, recv_;  // host staging per link
  mutable PendingExchange pending_;                       // the exchange in flight, if any
  mutable Direction pending_direction_ = Direction::owners_to_copies;
  mutable bool in_flight_ = false;
};

}  // namespace rouleau
