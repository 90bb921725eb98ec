#include "distributed/node_halo.hpp"

#include <KokkosBlas1_dot.hpp>
#include <stdexcept>
#include <string>

#include "util/view_transfer.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
using Vector = NodeHalo::Vector;
using ConstVector = NodeHalo::ConstVector;

// buffer(c·i + k) = values(c·nodes(i) + k)
void gather_nodes(const Kokkos::View<int*>& nodes, const int components, const ConstVector& values,
                  const Vector& buffer) {
  Kokkos::parallel_for(
      "rouleau::NodeHalo::gather", Kokkos::RangePolicy<ExecSpace>(0, nodes.extent(0)), KOKKOS_LAMBDA(const int i) {
        for (int k = 0; k < components; ++k) buffer(components * i + k) = values(components * nodes(i) + k);
      });
}

// values(c·nodes(i) + k) = buffer(c·i + k), or += with `add`
void scatter_nodes(const Kokkos::View<int*>& nodes, const int components, const ConstVector& buffer,
                   const Vector& values, const bool add) {
  Kokkos::parallel_for(
      "rouleau::NodeHalo::scatter", Kokkos::RangePolicy<ExecSpace>(0, nodes.extent(0)), KOKKOS_LAMBDA(const int i) {
        for (int k = 0; k < components; ++k) {
          double& entry = values(components * nodes(i) + k);
          entry = add ? entry + buffer(components * i + k) : buffer(components * i + k);
        }
      });
}

// host vector ← device buffer, and back
void to_host(const Vector& buffer, std::vector<double>& host) {
  Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> target(host.data(), host.size());
  Kokkos::deep_copy(target, buffer);
}
void to_device(const std::vector<double>& host, const Vector& buffer) {
  Kokkos::View<const double*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> source(host.data(), host.size());
  Kokkos::deep_copy(buffer, source);
}
}  // namespace

NodeHalo::NodeHalo(const Communicator& communicator, const ElementPartition& partition, int components)
    : communicator_(communicator), components_(components), owned_entries_(components * partition.num_owned_nodes) {
  if (partition.rank != communicator.rank() || partition.num_ranks != communicator.size())
    throw std::invalid_argument("rouleau::NodeHalo: the partition is for rank " + std::to_string(partition.rank) +
                                " of " + std::to_string(partition.num_ranks) + ", the communicator is rank " +
                                std::to_string(communicator.rank()) + " of " + std::to_string(communicator.size()));
  for (const NeighborExchange& neighbor : partition.neighbors) {
    Link link;
    link.rank = neighbor.rank;
    link.owned_shared = device_copy(neighbor.owned_shared, "rouleau::NodeHalo::owned_shared");
    link.copies = device_copy(neighbor.copies, "rouleau::NodeHalo::copies");
    link.owned_buffer = Vector("rouleau::NodeHalo::owned_buffer", components * neighbor.owned_shared.size());
    link.copy_buffer = Vector("rouleau::NodeHalo::copy_buffer", components * neighbor.copies.size());
    links_.push_back(link);
    ranks_.push_back(neighbor.rank);
  }
  send_.resize(links_.size());
  recv_.resize(links_.size());
}

void NodeHalo::start(const Direction direction, const Vector& values) const {
  if (in_flight_) throw std::logic_error("rouleau::NodeHalo: an exchange is already in flight");
  const bool to_copies = direction == Direction::owners_to_copies;
  for (std::size_t k = 0; k < links_.size(); ++k) {
    const Link& link = links_[k];
    const Vector& outgoing = to_copies ? link.owned_buffer : link.copy_buffer;
    gather_nodes(to_copies ? link.owned_shared : link.copies, components_, values, outgoing);
    send_[k].resize(outgoing.extent(0));
    recv_[k].resize(to_copies ? link.copy_buffer.extent(0) : link.owned_buffer.extent(0));
    to_host(outgoing, send_[k]);
  }
  pending_ = communicator_.start_exchange(ranks_, send_, recv_);
  pending_direction_ = direction;
  in_flight_ = true;
}

void NodeHalo::finish(const Vector& values) const {
  if (!in_flight_) throw std::logic_error("rouleau::NodeHalo::finish: no exchange in flight");
  pending_.wait();
  in_flight_ = false;
  const bool to_copies = pending_direction_ == Direction::owners_to_copies;
  // One link after the other (ascending rank): a node shared with several ranks takes
  // their partial sums in a fixed order.
  for (std::size_t k = 0; k < links_.size(); ++k) {
    const Link& link = links_[k];
    const Vector& incoming = to_copies ? link.copy_buffer : link.owned_buffer;
    to_device(recv_[k], incoming);
    scatter_nodes(to_copies ? link.copies : link.owned_shared, components_, incoming, values, !to_copies);
  }
}

void NodeHalo::start_update_copies(const Vector& values) const { start(Direction::owners_to_copies, values); }

void NodeHalo::start_add_copies_to_owners(const Vector& values) const { start(Direction::copies_to_owners, values); }

void NodeHalo::update_copies(const Vector& values) const {
  start_update_copies(values);
  finish(values);
}

void NodeHalo::add_copies_to_owners(const Vector& values) const {
  start_add_copies_to_owners(values);
  finish(values);
}

void NodeHalo::sum_into_owners(const Vector& values) const {
  add_copies_to_owners(values);
  update_copies(values);
}

double NodeHalo::dot(const ConstVector& x, const ConstVector& y) const {
  const auto owned = std::make_pair(0, owned_entries_);
  return communicator_.sum(KokkosBlas::dot(Kokkos::subview(x, owned), Kokkos::subview(y, owned)));
}

long long NodeHalo::values_per_update() const {
  long long values = 0;
  for (const Link& link : links_) values += static_cast<long long>(link.owned_buffer.extent(0));
  return values;
}

}  // namespace rouleau
