#include "distributed/node_sums.hpp"

#include <stdexcept>
#include <string>
#include <type_traits>

namespace rouleau {

namespace {
// Whether the element loops run on a device (their scatter buffers are atomic, not per thread).
constexpr bool loops_on_a_device =
    !std::is_same<Kokkos::DefaultExecutionSpace::memory_space, Kokkos::HostSpace>::value;
}  // namespace

NodeSums::NodeSums(const Communicator& communicator, const ElementPartition& partition)
    : communicator_(communicator), partition_(partition), overlap_(loops_on_a_device) {}

const NodeHalo& NodeSums::halo(const Kokkos::View<double*>& values, int components) const {
  if (static_cast<long>(values.extent(0)) != static_cast<long>(components) * partition_.num_local_nodes())
    throw std::logic_error("rouleau::NodeSums: a vector of " + std::to_string(values.extent(0)) + " entries is not " +
                           std::to_string(components) + " per local node");
  std::unique_ptr<NodeHalo>& halo = halos_[components];
  if (!halo) halo = std::make_unique<NodeHalo>(communicator_, partition_, components);
  return *halo;
}

void NodeSums::complete(const Kokkos::View<double*>& values, int components) const {
  halo(values, components).sum_into_owners(values);
}

// The partial sums at the shared nodes go to their owners.
void NodeSums::start(const Kokkos::View<double*>& values, int components) const {
  halo(values, components).start_add_copies_to_owners(values);
}

// The owners add them (ascending rank) and send the totals to the copies.
void NodeSums::advance(const Kokkos::View<double*>& values, int components) const {
  const NodeHalo& h = halo(values, components);
  h.finish(values);
  h.start_update_copies(values);
}

// The copies take the totals.
void NodeSums::finish(const Kokkos::View<double*>& values, int components) const {
  halo(values, components).finish(values);
}

// The input's copies take their owners' values (the ghost exchange before an action).
void NodeSums::start_copies(const Kokkos::View<double*>& input) const {
  const NodeHalo& h = halo(input, 4);
  if (!overlap_) {
    h.update_copies(input);
    return;
  }
  h.start_update_copies(input);
  input_ = input;
  input_in_flight_ = true;
}

void NodeSums::await_copies() const {
  if (!input_in_flight_) return;
  input_in_flight_ = false;
  halo(input_, 4).finish(input_);
  input_ = Kokkos::View<double*>();
}

}  // namespace rouleau
