#pragma once
// From the mesh's element type to the element class the kernels are templated on.
#include "kernels/hex8.hpp"
#include "kernels/tet4.hpp"
#include "mesh/fluid_mesh.hpp"

namespace rouleau {

// Calls f(Hex8{}) or f(Tet4{}), the element of `type`, and returns what it returns. The
// body of f is instantiated for both; it must not define a KOKKOS_LAMBDA itself (CUDA
// forbids extended lambdas inside a lambda): it builds functors or calls a function
// template on the element.
template <class F>
decltype(auto) visit_fluid_element(FluidElementType type, F&& f) {
  if (type == FluidElementType::tetrahedron4) return f(Tet4{});
  return f(Hex8{});
}

// Quadrature points per element of `type` (the extent of the operator's stored geometry).
inline int fluid_quadrature_points(FluidElementType type) {
  return visit_fluid_element(type, [](auto element) { return decltype(element)::quadrature_points; });
}

}  // namespace rouleau
