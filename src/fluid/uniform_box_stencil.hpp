#pragma once
// The Stokes operator of a uniform box applied as a stencil from one reference element
// (kernels/fluid_stencil.hpp): what FluidOperator::linear_action runs when every element
// has the same matrix, instead of the element-by-element path. The two agree to round-off
// (tests/test_fluid_stencil.cpp); the stencil reads no per-element geometry and scatters
// nothing.
#include <Kokkos_Core.hpp>
#include <string>

#include "kernels/fluid_element.hpp"
#include "kernels/fluid_stencil.hpp"
#include "mesh/fluid_mesh.hpp"

namespace rouleau {

template <class ExecSpace>
class BasicUniformBoxStencil {
 public:
  BasicUniformBoxStencil() = default;
  // Checks the mesh: a structured box (make_box_mesh) whose elements all have element 0's
  // quadrature geometry (to 1e-12 of its largest entry) and size. `geometry` and
  // `element_size` are FluidOperator's (scaled).
  BasicUniformBoxStencil(const FluidMesh& mesh, const Kokkos::View<const double***>& geometry,
                         const Kokkos::View<const double*>& element_size);

  // Whether the mesh allows the stencil; if not, why (for the log and --explain).
  bool available() const { return available_; }
  const std::string& unavailable_reason() const { return unavailable_reason_; }

  // result = Aδ on every row (Dirichlet rows are the caller's), for coefficients `c` in the
  // Stokes limit (convection 0). The tables are rebuilt when `c` differs from the last
  // call's (a new time step), which costs one reference element: 128 element evaluations.
  void apply(const FluidCoefficients& c, const Kokkos::View<const double*>& direction,
             const Kokkos::View<double*>& result) const;

 private:
  void build_tables(const FluidCoefficients& c) const;
  bool available_ = false;
  std::string unavailable_reason_ = "not set up";
  StructuredDofNodes nodes_;
  int num_dof_nodes_ = 0;
  Kokkos::View<const double***> geometry_;
  Kokkos::View<const double*> element_size_;
  mutable bool tables_built_ = false;
  mutable FluidCoefficients tables_coefficients_;
  // [class][offset][entries], LayoutRight on every device: the kernels walk them by pointer.
  using Table = Kokkos::View<double***, Kokkos::LayoutRight>;
  mutable Table block_stencil_, viscous_stencil_, gradient_stencil_;
  mutable Kokkos::View<double*> gradient_;  // G(δ), 9 per dof node
};

using UniformBoxStencil = BasicUniformBoxStencil<Kokkos::DefaultExecutionSpace>;

extern template class BasicUniformBoxStencil<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
