#pragma once
// One output file and one checkpoint per run, whatever the rank count (docs/mpi.md):
// node-interleaved vectors gathered on one rank in the global numbering, and the reverse.
// A vector gathered this way is the same, entry for entry, for any number of ranks (each
// unknown is taken from its owner), so a checkpoint written on P ranks restarts on Q.
// The owned global ids travel to the root once, at construction; each gather then moves
// the owned values alone (MPI_Gatherv).
#include <Kokkos_Core.hpp>
#include <vector>

#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"

namespace rouleau {

class RootGather {
 public:
  RootGather(const Communicator& communicator, const ElementPartition& partition, int components, int root = 0);

  // On the root: the global vector (components per global dof node) from every rank's
  // owned entries of `local` (its prefix); on the other ranks: empty.
  std::vector<double> gather(const Kokkos::View<const double*>& local) const;
  // The rank's owned entries of `local` from `global` (read on the root only); the copies
  // are left as they were (NodeHalo::update_copies fills them).
  void scatter(const std::vector<double>& global, const Kokkos::View<double*>& local) const;

  bool is_root() const { return communicator_.rank() == root_; }

 private:
  Communicator communicator_;
  int components_, root_, owned_entries_;
  std::vector<int> owner_global_nodes_;  // root: every rank's owned global nodes, rank after rank
  std::vector<int> entries_per_rank_;    // components × owned nodes, per rank (every rank)
  int global_nodes_;
};

}  // namespace rouleau
