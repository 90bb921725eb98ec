#include "fluid/uniform_box_stencil.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

namespace {

// Elements whose quadrature geometry or size differs from element 0's by more than
// `tolerance`, or whose dof nodes are not those of the structured numbering. (A free
// function: CUDA forbids extended lambdas in private member functions.)
template <class ExecSpace>
int count_irregular_elements(const FluidMesh& mesh, const StructuredDofNodes& nodes,
                             const Kokkos::View<const double***>& geometry,
                             const Kokkos::View<const double*>& element_size, double tolerance) {
  const int nx = mesh.structured_elements[0], ny = mesh.structured_elements[1];
  const auto dof_nodes = mesh.element_dof_nodes;
  const int points = static_cast<int>(geometry.extent(1)), entries = static_cast<int>(geometry.extent(2));
  int irregular = 0;
  Kokkos::parallel_reduce(
      "rouleau::UniformBoxStencil::check_mesh", Kokkos::RangePolicy<ExecSpace>(0, mesh.num_elements),
      KOKKOS_LAMBDA(const int e, int& count) {
        bool same = fabs(element_size(e) - element_size(0)) <= tolerance * element_size(0);
        for (int q = 0; q < points; ++q)
          for (int k = 0; k < entries; ++k) same = same && fabs(geometry(e, q, k) - geometry(0, q, k)) <= tolerance;
        // Local node a sits at the element's corner (0 or 1 per direction, Hex8's order).
        const int ijk[3] = {e % nx, (e / nx) % ny, e / (nx * ny)};
        for (int a = 0; a < 8; ++a) {
          const int o[3] = {Hex8::node_sign(a, 0) > 0, Hex8::node_sign(a, 1) > 0, Hex8::node_sign(a, 2) > 0};
          same = same && nodes.neighbor(ijk, o) == dof_nodes(e, a);
        }
        if (!same) ++count;
      },
      irregular);
  return irregular;
}

// Local index of the hexahedron node at corner (x, y, z) ∈ {0, 1}³, in Hex8's order.
int hex_corner_index(int x, int y, int z) {
  const int corner[3] = {x, y, z};
  for (int a = 0; a < Hex8::nodes; ++a) {
    bool here = true;
    for (int d = 0; d < 3; ++d) here = here && (Hex8::node_sign(a, d) > 0) == (corner[d] == 1);
    if (here) return a;
  }
  throw std::logic_error("rouleau::UniformBoxStencil: no hexahedron corner (" + std::to_string(x) + ", " +
                         std::to_string(y) + ", " + std::to_string(z) + ")");
}

bool same_coefficients(const FluidCoefficients& a, const FluidCoefficients& b) {
  return a.reynolds == b.reynolds && a.mass_coefficient == b.mass_coefficient && a.inverse_dt == b.inverse_dt &&
         a.convection == b.convection && a.lsic == b.lsic && a.viscous_reconstruction == b.viscous_reconstruction;
}
}  // namespace

template <class ExecSpace>
BasicUniformBoxStencil<ExecSpace>::BasicUniformBoxStencil(const FluidMesh& mesh,
                                                          const Kokkos::View<const double***>& geometry,
                                                          const Kokkos::View<const double*>& element_size)
    : num_dof_nodes_(mesh.num_dof_nodes), geometry_(geometry), element_size_(element_size) {
  if (mesh.element_type != FluidElementType::hexahedron8 || mesh.structured_elements[0] <= 0) {
    unavailable_reason_ = "the mesh is not a structured box of hexahedra";
    return;
  }
  for (int d = 0; d < 3; ++d) {
    nodes_.periodic[d] = mesh.periodic[d] ? 1 : 0;
    nodes_.planes[d] = mesh.structured_elements[d] + (mesh.periodic[d] ? 0 : 1);
  }
  if (nodes_.planes[0] * nodes_.planes[1] * nodes_.planes[2] != mesh.num_dof_nodes)
    throw std::logic_error("rouleau::UniformBoxStencil: the box's dof node count does not match its planes");
  // Geometry entries are O(1/h) and O(h³) in scaled units; compare against the largest.
  auto first = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(geometry, 0, Kokkos::ALL(), Kokkos::ALL()));
  double largest = 0.0;
  for (std::size_t q = 0; q < first.extent(0); ++q)
    for (std::size_t k = 0; k < first.extent(1); ++k) largest = std::fmax(largest, std::fabs(first(q, k)));
  const int irregular = count_irregular_elements<ExecSpace>(mesh, nodes_, geometry, element_size, 1e-12 * largest);
  if (irregular > 0) {
    std::ostringstream why;
    why << irregular << " of " << mesh.num_elements << " elements differ from the first (a graded box)";
    unavailable_reason_ = why.str();
    return;
  }
  available_ = true;
  unavailable_reason_.clear();
  block_stencil_ = Table("rouleau::UniformBoxStencil::block_stencil", stencil_node_classes,
                                           stencil_offsets, 16);
  viscous_stencil_ = Table("rouleau::UniformBoxStencil::viscous_stencil", stencil_node_classes,
                                             stencil_offsets, 9);
  gradient_stencil_ = Table("rouleau::UniformBoxStencil::gradient_stencil", stencil_node_classes,
                                              stencil_offsets, 3);
  gradient_ = Kokkos::View<double*>("rouleau::UniformBoxStencil::gradient", 9 * mesh.num_dof_nodes);
}

// The stencil of each node class is the sum of the reference element's matrices over the
// elements the class has: a node on the lower side of direction d lies at corner 0 of its
// elements along d, one on the upper side at corner 1, an inside node at both. For the
// element whose corner s is the node, the node's local index is a = corner(s), and local
// node b (corner c_b) sits at the offset o = c_b − s.
template <class ExecSpace>
void BasicUniformBoxStencil<ExecSpace>::build_tables(const FluidCoefficients& c) const {
  ProfilingRegion region("rouleau::UniformBoxStencil::build_tables");
  if (c.convection) throw std::logic_error("rouleau::UniformBoxStencil: the stencil is for the Stokes limit only");
  Kokkos::View<double**> element_matrix("rouleau::UniformBoxStencil::element_matrix", 32, 32);
  Kokkos::View<double**> gradient_response("rouleau::UniformBoxStencil::gradient_response", 72, 32);
  Kokkos::View<double**> moment_matrix("rouleau::UniformBoxStencil::moment_matrix", 24, 72);
  Kokkos::View<double*> mass("rouleau::UniformBoxStencil::mass", 8);
  ReferenceElementColumnsFunctor columns{FluidElementData{{}, geometry_, element_size_, c},
                                         element_matrix, gradient_response, moment_matrix, mass};
  Kokkos::parallel_for("rouleau::UniformBoxStencil::reference_element",
                       Kokkos::RangePolicy<ExecSpace>(0, ReferenceElementColumnsFunctor::columns), columns);
  auto K = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), element_matrix);
  auto B = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), gradient_response);
  auto P = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), moment_matrix);
  auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mass);
  // ∫ N_a ∂_j u_i depends on u_i alone, with a weight ∫ N_a ∂_j N_b that is the same for
  // every i: the stencil keeps one weight per j.
  for (int b = 0; b < 8; ++b)
    for (int a = 0; a < 8; ++a)
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            if (P(3 * b + c, 9 * a + 3 * i + j) != (c == i ? P(3 * b, 9 * a + j) : 0.0))
              throw std::logic_error("rouleau::UniformBoxStencil: the gradient moments are not componentwise");
  // In the Stokes limit G reaches only the pressure rows (PSPG); the stencil keeps no more.
  for (int col = 0; col < 72; ++col)
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i)
        if (B(col, 4 * a + i) != 0.0)
          throw std::logic_error("rouleau::UniformBoxStencil: the projected gradient reaches a momentum row");

  auto block = Kokkos::create_mirror_view(block_stencil_);
  auto viscous = Kokkos::create_mirror_view(viscous_stencil_);
  auto gradient = Kokkos::create_mirror_view(gradient_stencil_);
  Kokkos::deep_copy(block, 0.0);
  Kokkos::deep_copy(viscous, 0.0);
  Kokkos::deep_copy(gradient, 0.0);
  for (int t = 0; t < stencil_node_classes; ++t) {
    const int node_class[3] = {t % 3, (t / 3) % 3, t / 9};
    double lumped_mass = 0.0;
    for (int s = 0; s < 8; ++s) {
      const int corner[3] = {s & 1, (s >> 1) & 1, (s >> 2) & 1};  // the node's corner in this element
      bool present = true;
      for (int d = 0; d < 3; ++d)
        present = present && !(node_class[d] == 0 && corner[d] == 1) && !(node_class[d] == 2 && corner[d] == 0);
      if (!present) continue;
      const int a = hex_corner_index(corner[0], corner[1], corner[2]);
      lumped_mass += m(a);
      for (int cb = 0; cb < 8; ++cb) {
        const int other[3] = {cb & 1, (cb >> 1) & 1, (cb >> 2) & 1};
        const int b = hex_corner_index(other[0], other[1], other[2]);
        const int o = stencil_offset_index(other[0] - corner[0], other[1] - corner[1], other[2] - corner[2]);
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) block(t, o, 4 * j + i) += K(4 * b + j, 4 * a + i);
        for (int k = 0; k < 9; ++k) viscous(t, o, k) += B(9 * b + k, 4 * a + 3);
        for (int j = 0; j < 3; ++j) gradient(t, o, j) += P(3 * b, 9 * a + j);
      }
    }
    for (int o = 0; o < stencil_offsets; ++o)
      for (int j = 0; j < 3; ++j) gradient(t, o, j) /= lumped_mass;
  }
  Kokkos::deep_copy(block_stencil_, block);
  Kokkos::deep_copy(viscous_stencil_, viscous);
  Kokkos::deep_copy(gradient_stencil_, gradient);
  tables_coefficients_ = c;
  tables_built_ = true;
}

template <class ExecSpace>
void BasicUniformBoxStencil<ExecSpace>::apply(const FluidCoefficients& c, const Kokkos::View<const double*>& direction,
                                              const Kokkos::View<double*>& result) const {
  if (!available_) throw std::logic_error("rouleau::UniformBoxStencil::apply: " + unavailable_reason_);
  if (!tables_built_ || !same_coefficients(c, tables_coefficients_)) build_tables(c);
  ProfilingRegion region("rouleau::UniformBoxStencil::apply");
  Kokkos::View<const double*> gradient;
  if (c.viscous_reconstruction) {
    StencilGradientFunctor g{nodes_, gradient_stencil_, direction, gradient_};
    Kokkos::parallel_for("rouleau::UniformBoxStencil::gradient", Kokkos::RangePolicy<ExecSpace>(0, num_dof_nodes_), g);
    gradient = gradient_;
  }
  StencilActionFunctor f{nodes_, block_stencil_, viscous_stencil_, direction, gradient, result};
  Kokkos::parallel_for("rouleau::UniformBoxStencil::action", Kokkos::RangePolicy<ExecSpace>(0, num_dof_nodes_), f);
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicUniformBoxStencil)

}  // namespace rouleau
