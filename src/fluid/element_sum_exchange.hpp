#pragma once
// How a rank's element loops complete their sums across ranks, as
// FluidOperator::set_node_sums sees it; distributed/node_sums.hpp implements it with MPI.
//
// After an element loop each shared dof node holds this rank's partial sum; the exchange
// adds the other ranks' and leaves every local entry, owned or copy, with the value the
// whole mesh gives. The rank's elements are ordered so that [0, boundary_elements()) are
// those touching a shared node and the rest (the interior) touch none: the interior
// neither reads a copy nor adds to a shared node, so it is summed while messages travel.
// An operator's input may come with its copies still travelling from their owners
// (start_copies, the ghost exchange before an action); then a loop runs
//
//   interior, first third → await_copies → boundary elements → start → interior, second
//   third → advance → interior, last third → finish → the interior's sums added
//
// and without copies in flight the interior in halves around advance. start() posts the
// partial sums to the owners; advance() adds what arrived at the owners and posts the
// totals to the copies; finish() stores them. complete() does all three at once, for loops
// that do not overlap.
#include <Kokkos_Core.hpp>

namespace rouleau {

class ElementSumExchange {
 public:
  virtual ~ElementSumExchange() = default;
  virtual int boundary_elements() const = 0;
  // Whether the element loops overlap the exchange with the interior (otherwise: loop,
  // then complete()). The two agree to round-off.
  virtual bool overlaps() const = 0;
  // `values`: node-interleaved, `components` per local dof node.
  virtual void complete(const Kokkos::View<double*>& values, int components) const = 0;
  virtual void start(const Kokkos::View<double*>& values, int components) const = 0;
  virtual void advance(const Kokkos::View<double*>& values, int components) const = 0;
  virtual void finish(const Kokkos::View<double*>& values, int components) const = 0;
  // The ghost exchange of an input (4 values per local dof node): its copies take their
  // owners' values, posted by start_copies() and complete after await_copies(), which
  // every element loop calls before it reads a copy (nothing to do when none is in flight).
  virtual void start_copies(const Kokkos::View<double*>& input) const = 0;
  virtual bool copies_in_flight() const = 0;
  virtual void await_copies() const = 0;
};

}  // namespace rouleau
