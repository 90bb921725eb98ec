#pragma once
// How a rank's element loops complete their sums across ranks (issue 10), as
// FluidOperator::set_node_sums sees it; distributed/node_sums.hpp implements it with MPI.
//
// After an element loop each shared dof node holds this rank's partial sum; the exchange
// adds the other ranks' and leaves every local entry, owned or copy, with the value the
// whole mesh gives. The rank's elements are ordered so that [0, boundary_elements()) are
// those touching a shared node and the rest (the interior) touch none: their sums are
// final once the boundary elements are summed, and the interior elements run while the
// messages travel:
//
//   boundary elements → start → interior, first half → advance → interior, second half
//   → finish → the interior's sums added
//
// start() posts the partial sums to the owners; advance() adds what arrived at the owners
// and posts the totals to the copies; finish() stores them. complete() does all three at
// once, for loops that do not overlap.
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
};

}  // namespace rouleau
