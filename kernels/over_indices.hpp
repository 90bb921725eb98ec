#pragma once
// A kernel launched over a list of indices instead of a range: over [0, n) it calls the
// wrapped functor at indices(i). It runs the force kernels over the elements, surface
// triangles and cells a rank computes (CellPopulation::share_work), listed in ascending
// order so that every sum keeps the order of the whole range.
#include <Kokkos_Core.hpp>

#include "kernels/launch_tags.hpp"

namespace rouleau {

template <class Functor>
struct OverIndices {
  Functor work;
  Kokkos::View<const int*> indices;

  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { work(indices(i)); }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesOnly tag, const int i) const { work(tag, indices(i)); }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesAndEnergy tag, const int i, double& energy) const {
    work(tag, indices(i), energy);
  }
};

template <class Functor>
OverIndices<Functor> over_indices(const Functor& work, const Kokkos::View<const int*>& indices) {
  return OverIndices<Functor>{work, indices};
}

}  // namespace rouleau
