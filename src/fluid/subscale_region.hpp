#pragma once
// Where the cells read PSPG's subscale velocity u' (coupling.subscale_velocity): u' at a
// node sums the moments of the elements around it, and with the viscous reconstruction
// each of those reads the projected velocity gradient at its nodes, which sums the
// elements around those. The cells read u' only at their RKPM supports' nodes, so two
// rings of elements around those nodes give it there exactly, at a fraction of the
// whole mesh's cost in the semi-implicit step, which applies the derivative of u' once per
// GMRES iteration (FluidOperator::subscale_velocity_action).
#include <Kokkos_Core.hpp>

namespace rouleau {

struct SubscaleRegion {
  // false: the whole mesh (what a field output or a rank-spanning mesh needs).
  bool restricted = false;
  // The elements with a node in the supports (whose moments u' sums there), and the
  // elements with a node in those (whose gradient projection they read).
  Kokkos::View<const int*> elements, gradient_elements;
};

}  // namespace rouleau
