#include "distributed/root_gather.hpp"

#include <stdexcept>
#include <string>

namespace rouleau {

RootGather::RootGather(const Communicator& communicator, const ElementPartition& partition, int components, int root)
    : communicator_(communicator),
      components_(components),
      root_(root),
      owned_entries_(components * partition.num_owned_nodes),
      global_nodes_(partition.num_global_nodes) {
  const std::vector<int> owned(partition.global_node.begin(), partition.global_node.begin() + partition.num_owned_nodes);
  owner_global_nodes_ = communicator.gather(owned, root);
  // every rank learns every rank's count (scatter needs them on all ranks)
  std::vector<double> count(communicator.size(), 0.0);
  count[communicator.rank()] = owned_entries_;
  communicator.sum(count.data(), communicator.size());
  for (const double c : count) entries_per_rank_.push_back(static_cast<int>(c));
  // Checked on every rank (a throw on the root alone would leave the others waiting in the
  // next collective): the ranks own every global node once.
  const long long owned_in_all = communicator.sum(static_cast<long long>(partition.num_owned_nodes));
  if (owned_in_all != global_nodes_)
    throw std::logic_error("rouleau::RootGather: the ranks own " + std::to_string(owned_in_all) + " nodes of " +
                           std::to_string(global_nodes_) + " (a node no element touches has no owner)");
}

std::vector<double> RootGather::gather(const Kokkos::View<const double*>& local) const {
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), local);
  const std::vector<double> owned(host.data(), host.data() + owned_entries_);
  const std::vector<double> arrived = communicator_.gather(owned, root_);
  if (!is_root()) return {};
  // arrived holds the ranks' owned nodes in the order of owner_global_nodes_
  std::vector<double> global(static_cast<std::size_t>(components_) * global_nodes_);
  for (std::size_t k = 0; k < owner_global_nodes_.size(); ++k)
    for (int c = 0; c < components_; ++c)
      global[static_cast<std::size_t>(components_) * owner_global_nodes_[k] + c] = arrived[components_ * k + c];
  return global;
}

void RootGather::scatter(const std::vector<double>& global, const Kokkos::View<double*>& local) const {
  std::vector<double> ordered;
  // the root's size check, on every rank (no rank may be left in MPI_Scatterv)
  const double wrong_size =
      communicator_.sum(is_root() && global.size() != static_cast<std::size_t>(components_) * global_nodes_ ? 1.0 : 0.0);
  if (wrong_size > 0.0)
    throw std::invalid_argument("rouleau::RootGather::scatter: the root's global vector does not hold " +
                                std::to_string(components_ * global_nodes_) + " entries");
  if (is_root()) {
    ordered.resize(global.size());
    for (std::size_t k = 0; k < owner_global_nodes_.size(); ++k)
      for (int c = 0; c < components_; ++c)
        ordered[components_ * k + c] = global[static_cast<std::size_t>(components_) * owner_global_nodes_[k] + c];
  }
  const std::vector<double> mine = communicator_.scatter(ordered, entries_per_rank_, root_);
  Kokkos::View<const double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> source(mine.data(), mine.size());
  Kokkos::deep_copy(Kokkos::subview(local, Kokkos::make_pair(0, owned_entries_)), source);
}

}  // namespace rouleau
