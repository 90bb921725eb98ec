#pragma once
// The matrix-free stabilized Navier–Stokes operator on a fixed mesh, in scaled variables.
//
// residual(U)        R(U) = Σ_e R_e(U) − b, with Dirichlet rows R_d = U_d − g_d
// jacobian_action    J(U)δ with τ frozen at U (exact, from dual numbers), Dirichlet rows δ_d
// linear_action      Aδ for an affine residual (the Stokes limit): R without sources
// diagonal_blocks    the 4×4 node blocks of J (for block Jacobi), Dirichlet rows identity
// The constant nodal load b holds traction loads and the immersed (spread) forces of
// paper eq. 16. The immersed forces may also enter the stabilization's strong residual as
// the force density they stand for (load_stabilization; kernels/fluid_element.hpp).
// Quadrature geometry is computed once, at construction: the mesh never moves.
#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>
#include <string>
#include <vector>

#include "fluid/element_sum_exchange.hpp"
#include "fluid/fluid_matrix.hpp"
#include "fluid/subscale_region.hpp"
#include "fluid/uniform_box_stencil.hpp"
#include "kernels/fluid_assembly.hpp"
#include "mesh/fluid_mesh.hpp"

namespace rouleau {

using Vector = Kokkos::View<double*>;
using ConstVector = Kokkos::View<const double*>;

// ExecSpace runs the element loops; the default execution space in production, and
// each host backend in the equivalence tests (all share the default memory space).
template <class ExecSpace>
class BasicFluidOperator {
 public:
  // `length_scale` [μm] scales the coordinates: the operator works in x/L.
  BasicFluidOperator(const FluidMesh& mesh, double length_scale);

  int num_unknowns() const { return num_unknowns_; }
  const FluidMesh& mesh() const { return mesh_; }
  const FluidCoefficients& coefficients() const { return coefficients_; }
  void set_coefficients(const FluidCoefficients& c) { coefficients_ = c; }

  // Dirichlet constraints: unknown indices and their (scaled) values.
  void set_dirichlet(const std::vector<int>& dofs, const std::vector<double>& values);
  const Kokkos::View<int*>& dirichlet_dofs() const { return dirichlet_dofs_; }
  const Kokkos::View<double*>& dirichlet_values() const { return dirichlet_values_; }
  // Sets U_d = g_d on the constrained unknowns.
  void impose_dirichlet(const Vector& state) const;

  // The constant nodal load b (scaled): traction loads; an empty View means none.
  void set_nodal_load(const Vector& load) { nodal_load_ = load; }
  // The immersed forces' nodal loads (scaled, velocity entries), a second part of b; with
  // `in_stabilization` their force density also enters SUPG/PSPG's strong residual.
  void set_immersed_load(const ConstVector& load) { immersed_load_ = load; }
  void set_immersed_load_in_stabilization(bool in_stabilization) {
    immersed_load_in_stabilization_ = in_stabilization;
  }
  bool immersed_load_in_stabilization() const { return immersed_load_in_stabilization_; }
  // result = the stabilization's share of nodal loads `load` (τ and the SUPG weight from
  // `frozen`): the terms −Re τ c (u·∇N_a) f_h and −τ ∇N_a·f_h, f_h = Σ N_b b_b/m_b.
  void load_stabilization(const ConstVector& frozen, const ConstVector& load, const Vector& result) const;
  // result = PSPG's subscale velocity of `state` projected onto the nodes (scaled, velocity
  // entries; pressure entries and Dirichlet velocity entries 0): u'_a = −(1/m_a) ∫ N_a τ_M r,
  // r the strong momentum residual with the current sources (FluidSubscaleFunctor). With a
  // restricted `region` only its elements are visited: u' is exact at the nodes whose
  // elements all lie in region.elements and partial elsewhere.
  void subscale_velocity(const ConstVector& state, const Vector& result, const SubscaleRegion& region = {}) const;
  // result = its derivative along `direction` with τ frozen at `state`, projected the same
  // way (FluidSubscaleActionFunctor): the linear part of u' that the semi-implicit
  // coupling's Jacobian needs when the cells move with u_h + u'. `region` as above.
  void subscale_velocity_action(const ConstVector& state, const ConstVector& direction, const Vector& result,
                                const SubscaleRegion& region = {}) const;
  // The two rings of elements around `nodes` (dof nodes) that give u' exactly at them
  // (fluid/subscale_region.hpp). On one rank only: across ranks the element loops' sums
  // are completed over the whole mesh, and this throws std::logic_error. The region views
  // the operator's buffers: valid until the next call.
  SubscaleRegion subscale_region_around(const Kokkos::View<const int*>& nodes) const;

  // The sources of the residual: BDF history H and nodal body force f (scaled, node-
  // interleaved like the state; only the velocity entries are read). Empty = zero.
  void set_sources(const ConstVector& history, const ConstVector& body_force) {
    history_ = history;
    body_force_ = body_force;
  }

  // R(U) with τ_M, ν_L computed from `frozen` (pass `state` for the usual residual).
  // `constrained_rows = false` leaves the element sums in the Dirichlet rows (the nodal
  // reaction forces there) instead of U_d − g_d.
  void residual(const ConstVector& state, const ConstVector& frozen, const Vector& result,
                bool constrained_rows = true) const;
  void jacobian_action(const ConstVector& state, const ConstVector& direction, const Vector& result) const;
  // The same with the projected gradient G(U) of `state` given (project_gradient), for
  // a Krylov solve that applies J(U) many times at one state.
  void jacobian_action(const ConstVector& state, const ConstVector& state_gradient, const ConstVector& direction,
                       const Vector& result) const;
  void linear_action(const ConstVector& direction, const Vector& result) const;
  // linear_action's path: on a uniform box (every element the same matrix) the Stokes
  // operator runs as a stencil from one reference element (fluid/uniform_box_stencil.hpp)
  // unless `allow` is false; elsewhere, and with `allow` false, element by element. The
  // two agree to round-off.
  void allow_stencil(bool allow) { stencil_allowed_ = allow; }
  bool uses_stencil() const { return stencil_allowed_ && stencil_.available() && !coefficients_.convection; }
  // Why the stencil is not used (empty when it is).
  std::string stencil_unavailable_reason() const;
  // blocks(16·node + 4i + j) = ∂R_(node,i)/∂U_(node,j)
  void diagonal_blocks(const ConstVector& state, const Vector& blocks) const;
  // The global Jacobian in CRS form on `graph` (with identity Dirichlet rows), for
  // assembled preconditioners; exact without viscous reconstruction, which it holds fixed.
  void assemble_jacobian(const ConstVector& state, const BlockMatrixGraph& graph, const Vector& values) const;
  // Element matrices K_e(4a+i, 4b+j) without Dirichlet rows (tests, assembly).
  void element_matrices(const ConstVector& state, const Kokkos::View<double***>& matrices) const;

  // The lumped L2 projection of the velocity gradient of `state` onto the dof nodes:
  // gradient(9·node + 3i + j) = G_node,ij ≈ ∂_j u_i (scaled).
  void project_gradient(const ConstVector& state, const Vector& gradient) const;
  // The same from the elements of `region` only (all when it is not restricted): exact at
  // the nodes whose every element is in the region. Public because its division by the
  // lumped mass is a device lambda, which CUDA forbids inside a private member.
  void project_gradient(const ConstVector& state, const Vector& gradient, const SubscaleRegion& region) const;

  // Distributed runs: `sums` completes every vector of element sums
  // (node-interleaved, `components` per dof node: 1 lumped mass, 4 residuals and actions,
  // 9 projected gradients, 16 diagonal blocks) right after its element loop and before any
  // constrained row, load or division reads it: on a rank's mesh it adds the other ranks'
  // partial sums at the shared nodes (distributed/node_sums.hpp). The element loops of the
  // actions, projections and blocks overlap its exchanges with the interior elements
  // (fluid/element_sum_exchange.hpp); the residual's loop completes after it. The lumped
  // mass is completed when it is set. Null (the default): one rank, nothing to add. `sums`
  // must outlive the operator. The assembled Jacobian (assemble_jacobian) is not completed
  // this way.
  void set_node_sums(const ElementSumExchange* sums);
  // Across ranks: the copies of `input` (a local vector, 4 per dof node) take their owners'
  // values while the next element loop sums interior elements, before it reads a copy. One
  // rank: nothing to fill.
  void start_filling_copies(const Vector& input) const;
  bool has_node_sums() const { return node_sums_ != nullptr; }

  // Geometry stored per quadrature point (scaled): [e][q][(J⁻¹)_kd, det J·w].
  const Kokkos::View<double***>& geometry() const { return geometry_; }
  const Kokkos::View<double*>& element_size() const { return element_size_; }
  // The lumped mass m_a = Σ_e ∫ N_a dV per dof node (scaled).
  const Kokkos::View<double*>& lumped_mass() const { return lumped_mass_; }
  double length_scale() const { return length_scale_; }

 private:
  using Scatter = Kokkos::Experimental::ScatterView<double*, typename Vector::array_layout,
                                                    typename ExecSpace::device_type>;
  FluidElementData element_data() const;
  Scatter& zeroed_scatter(Scatter& buffer, std::size_t size, const char* label) const;
  template <class Functor>
  void for_each_element(const char* label, const Functor& f, const Scatter& scatter, const Vector& target) const;
  // The same over the elements in `elements` only (one rank).
  template <class Functor>
  void for_each_listed_element(const char* label, const Functor& f, const Kokkos::View<const int*>& elements,
                               const Scatter& scatter, const Vector& target) const;
  // target's element sums completed across ranks (node_sums_), when there are ranks
  void await_copies() const;
  void complete_node_sums(const Vector& target) const;
  const ElementSumExchange* node_sums_ = nullptr;
  FluidMesh mesh_;
  double length_scale_;
  int num_unknowns_;
  FluidCoefficients coefficients_;
  Kokkos::View<double***> geometry_;
  Kokkos::View<double*> element_size_;
  Kokkos::View<int*> dirichlet_dofs_;
  Kokkos::View<double*> dirichlet_values_;
  Vector nodal_load_;
  ConstVector immersed_load_;
  bool immersed_load_in_stabilization_ = false;
  ConstVector history_, body_force_;
  // The elements grouped by colour (no two of a colour share a dof node), for a CRS
  // assembly without atomics: colored_elements_[color_offsets_[c], color_offsets_[c+1]).
  void color_elements() const;
  mutable Kokkos::View<int*> colored_elements_;
  mutable std::vector<int> color_offsets_;
  Kokkos::View<double*> lumped_mass_;                        // Σ_e ∫ N_a dV per dof node
  BasicUniformBoxStencil<ExecSpace> stencil_;
  bool stencil_allowed_ = true;
  Kokkos::View<double*> state_gradient_, direction_gradient_;  // scratch for G(U), G(δ)
  // Persistent scatter buffers of the element loops (per-thread copies on CPUs, the
  // atomic target on GPUs), for results of the unknowns', gradients' and blocks' sizes.
  mutable Scatter unknowns_scatter_, gradient_scatter_, blocks_scatter_;
  // subscale_region_around's buffers: node flags, and room for every element in each list.
  mutable Kokkos::View<int*> region_node_flags_, region_elements_, region_gradient_elements_;
};

using FluidOperator = BasicFluidOperator<Kokkos::DefaultExecutionSpace>;

// Instantiated (in fluid_operator.cpp) for every enabled execution space that can reach
// the default memory space.
extern template class BasicFluidOperator<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
