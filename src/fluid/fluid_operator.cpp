#include "fluid/fluid_operator.hpp"

#include <Kokkos_ScatterView.hpp>
#include <cstdint>
#include <sstream>
#include <utility>
#include <stdexcept>
#include <string>

#include "kernels/fluid_assembly.hpp"
#include "fluid/fluid_element_types.hpp"
#include "kernels/scatter_sum.hpp"
#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

namespace {

// Dirichlet rows: R_d = U_d − g_d for a residual, (Jδ)_d = δ_d for an action. (A free
// function: CUDA forbids extended lambdas in private member functions.)
template <class ExecSpace>
void apply_dirichlet_rows(const Kokkos::View<int*>& dofs, const Kokkos::View<double*>& values,
                          const ConstVector& state, const ConstVector& direction, bool residual_rows,
                          const Vector& result) {
  Kokkos::parallel_for(
      "rouleau::FluidOperator::dirichlet_rows", Kokkos::RangePolicy<ExecSpace>(0, dofs.extent(0)),
      KOKKOS_LAMBDA(const int i) {
        const int d = dofs(i);
        result(d) = residual_rows ? state(d) - values(i) : direction(d);
      });
}

// result −= load (an empty load is none).
template <class ExecSpace>
void subtract_nodal_load(const ConstVector& load, const Vector& result) {
  if (load.extent(0) == 0) return;
  Kokkos::parallel_for(
      "rouleau::FluidOperator::nodal_load", Kokkos::RangePolicy<ExecSpace>(0, load.extent(0)),
      KOKKOS_LAMBDA(const int i) { result(i) -= load(i); });
}
}  // namespace

template <class ExecSpace>
BasicFluidOperator<ExecSpace>::BasicFluidOperator(const FluidMesh& mesh, double length_scale)
    : mesh_(mesh), length_scale_(length_scale), num_unknowns_(mesh.num_unknowns()) {
  ProfilingRegion region("rouleau::FluidOperator::setup");
  geometry_ = Kokkos::View<double***>("rouleau::FluidOperator::geometry", mesh_.num_elements,
                                      fluid_quadrature_points(mesh_.element_type), geometry_entries);
  element_size_ = Kokkos::View<double*>("rouleau::FluidOperator::element_size", mesh_.num_elements);
  int inverted = 0;
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidGeometryFunctor<decltype(element)> geometry{mesh_.coordinates, mesh_.element_nodes, 1.0 / length_scale_,
                                                     geometry_, element_size_};
    Kokkos::parallel_reduce("rouleau::FluidOperator::geometry",
                            Kokkos::RangePolicy<ExecSpace>(0, mesh_.num_elements), geometry, inverted);
  });
  if (inverted > 0) {
    std::ostringstream msg;
    msg << "rouleau::FluidOperator: the mesh has " << inverted
        << " quadrature points with det J <= 0 (inverted or degenerate elements)";
    throw std::invalid_argument(msg.str());
  }
  lumped_mass_ = Kokkos::View<double*>("rouleau::FluidOperator::lumped_mass", mesh_.num_dof_nodes);
  state_gradient_ = Kokkos::View<double*>("rouleau::FluidOperator::state_gradient", 9 * mesh_.num_dof_nodes);
  direction_gradient_ =
      Kokkos::View<double*>("rouleau::FluidOperator::direction_gradient", 9 * mesh_.num_dof_nodes);
  Vector zero("rouleau::FluidOperator::zero", num_unknowns_);
  // The lumped mass comes with a gradient projection of the zero field (discarded).
  Scatter& gradient = zeroed_scatter(gradient_scatter_, state_gradient_.extent(0),
                                     "rouleau::FluidOperator::gradient_scatter");
  Scatter mass_scatter("rouleau::FluidOperator::mass_scatter", mesh_.num_dof_nodes);
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidGradientProjectionFunctor<decltype(element), Scatter> mass{element_data(), zero, gradient, mass_scatter,
                                                                    true};
    for_each_element("rouleau::FluidOperator::lumped_mass", mass, mass_scatter, lumped_mass_);
  });
  stencil_ = BasicUniformBoxStencil<ExecSpace>(mesh_, geometry_, element_size_);
}

template <class ExecSpace>
std::string BasicFluidOperator<ExecSpace>::stencil_unavailable_reason() const {
  if (uses_stencil()) return "";
  if (!stencil_allowed_) return "the stencil path is switched off";
  if (coefficients_.convection) return "the convective term makes every element's matrix differ";
  return stencil_.unavailable_reason();
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::project_gradient(const ConstVector& state, const Vector& gradient) const {
  project_gradient(state, gradient, SubscaleRegion{});
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::project_gradient(const ConstVector& state, const Vector& gradient,
                                                     const SubscaleRegion& subset) const {
  ProfilingRegion region("rouleau::FluidOperator::project_gradient");
  Scatter& scatter = zeroed_scatter(gradient_scatter_, gradient.extent(0), "rouleau::FluidOperator::gradient_scatter");
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidGradientProjectionFunctor<decltype(element), Scatter> f{element_data(), state, scatter, scatter, false};
    if (subset.restricted)
      for_each_listed_element("rouleau::FluidOperator::project_gradient", f, subset.gradient_elements, scatter,
                              gradient);
    else
      for_each_element("rouleau::FluidOperator::project_gradient", f, scatter, gradient);
  });
  auto mass = lumped_mass_;
  Kokkos::parallel_for(
      "rouleau::FluidOperator::project_gradient::divide", Kokkos::RangePolicy<ExecSpace>(0, gradient.extent(0)),
      KOKKOS_LAMBDA(const int k) { gradient(k) /= mass(k / 9); });
}

template <class ExecSpace>
FluidElementData BasicFluidOperator<ExecSpace>::element_data() const {
  return FluidElementData{mesh_.element_dof_nodes, geometry_, element_size_, coefficients_};
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::set_dirichlet(const std::vector<int>& dofs, const std::vector<double>& values) {
  if (dofs.size() != values.size()) throw std::invalid_argument("rouleau::FluidOperator::set_dirichlet: sizes differ");
  dirichlet_dofs_ = Kokkos::View<int*>("rouleau::FluidOperator::dirichlet_dofs", dofs.size());
  dirichlet_values_ = Kokkos::View<double*>("rouleau::FluidOperator::dirichlet_values", values.size());
  auto d = Kokkos::create_mirror_view(dirichlet_dofs_);
  auto v = Kokkos::create_mirror_view(dirichlet_values_);
  for (size_t i = 0; i < dofs.size(); ++i) {
    d(i) = dofs[i];
    v(i) = values[i];
  }
  Kokkos::deep_copy(dirichlet_dofs_, d);
  Kokkos::deep_copy(dirichlet_values_, v);
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::impose_dirichlet(const Vector& state) const {
  auto dofs = dirichlet_dofs_;
  auto values = dirichlet_values_;
  Kokkos::parallel_for(
      "rouleau::FluidOperator::impose_dirichlet", Kokkos::RangePolicy<ExecSpace>(0, dofs.extent(0)),
      KOKKOS_LAMBDA(const int i) { state(dofs(i)) = values(i); });
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::residual(const ConstVector& state, const ConstVector& frozen, const Vector& result,
                             bool constrained_rows) const {
  ProfilingRegion region("rouleau::FluidOperator::residual");
  await_copies();
  if (coefficients_.viscous_reconstruction) project_gradient(state, state_gradient_);
  Scatter& scatter = zeroed_scatter(unknowns_scatter_, result.extent(0), "rouleau::FluidOperator::unknowns_scatter");
  const bool stabilized_load = immersed_load_.extent(0) > 0 && immersed_load_in_stabilization_;
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    using Element = decltype(element);
    FluidResidualFunctor<Element, Scatter> f{element_data(), state, frozen, history_, body_force_, state_gradient_,
                                             scatter};
    Kokkos::parallel_for("rouleau::FluidOperator::residual", Kokkos::RangePolicy<ExecSpace>(0, mesh_.num_elements), f);
    if (stabilized_load) {
      FluidLoadStabilizationFunctor<Element, Scatter> g{element_data(), frozen, immersed_load_, lumped_mass_, scatter};
      Kokkos::parallel_for("rouleau::FluidOperator::load_stabilization",
                           Kokkos::RangePolicy<ExecSpace>(0, mesh_.num_elements), g);
    }
    gather_into(result, scatter);
  });
  complete_node_sums(result);
  subtract_nodal_load<ExecSpace>(nodal_load_, result);
  subtract_nodal_load<ExecSpace>(immersed_load_, result);
  if (constrained_rows) apply_dirichlet_rows<ExecSpace>(dirichlet_dofs_, dirichlet_values_, state, state, true, result);
}

namespace {
// u'_a = −M_a / m_a from the moments M in `result`, on the velocity entries; none on the
// pressure and Dirichlet entries.
template <class ExecSpace>
void project_subscale_moments(const Kokkos::View<const double*>& lumped_mass, const Kokkos::View<const int*>& dirichlet_dofs,
                              const Vector& result) {
  Kokkos::parallel_for(
      "rouleau::FluidOperator::subscale_velocity::divide", Kokkos::RangePolicy<ExecSpace>(0, result.extent(0)),
      KOKKOS_LAMBDA(const int k) { result(k) = k % 4 == 3 ? 0.0 : -result(k) / lumped_mass(k / 4); });
  Kokkos::parallel_for(
      "rouleau::FluidOperator::subscale_velocity::dirichlet", Kokkos::RangePolicy<ExecSpace>(0, dirichlet_dofs.extent(0)),
      KOKKOS_LAMBDA(const int i) { result(dirichlet_dofs(i)) = 0.0; });
}
}  // namespace

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::subscale_velocity(const ConstVector& state, const Vector& result,
                                                      const SubscaleRegion& subset) const {
  ProfilingRegion region("rouleau::FluidOperator::subscale_velocity");
  if (coefficients_.viscous_reconstruction) project_gradient(state, state_gradient_, subset);
  Scatter& scatter = zeroed_scatter(unknowns_scatter_, result.extent(0), "rouleau::FluidOperator::unknowns_scatter");
  const ConstVector load = immersed_load_in_stabilization_ ? immersed_load_ : ConstVector();
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidSubscaleFunctor<decltype(element), Scatter> f{
        element_data(), state, history_, body_force_, state_gradient_, load, lumped_mass_, scatter};
    if (subset.restricted)
      for_each_listed_element("rouleau::FluidOperator::subscale_velocity", f, subset.elements, scatter, result);
    else
      for_each_element("rouleau::FluidOperator::subscale_velocity", f, scatter, result);
  });
  project_subscale_moments<ExecSpace>(lumped_mass_, dirichlet_dofs_, result);
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::subscale_velocity_action(const ConstVector& state, const ConstVector& direction,
                                                             const Vector& result, const SubscaleRegion& subset) const {
  ProfilingRegion region("rouleau::FluidOperator::subscale_velocity_action");
  // The derivative needs the projected gradient of δ, not of U (FluidSubscaleActionFunctor).
  if (coefficients_.viscous_reconstruction) project_gradient(direction, direction_gradient_, subset);
  Scatter& scatter = zeroed_scatter(unknowns_scatter_, result.extent(0), "rouleau::FluidOperator::unknowns_scatter");
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidSubscaleActionFunctor<decltype(element), Scatter> f{
        element_data(), state, direction, direction_gradient_, scatter};
    if (subset.restricted)
      for_each_listed_element("rouleau::FluidOperator::subscale_velocity_action", f, subset.elements, scatter, result);
    else
      for_each_element("rouleau::FluidOperator::subscale_velocity_action", f, scatter, result);
  });
  project_subscale_moments<ExecSpace>(lumped_mass_, dirichlet_dofs_, result);
}

namespace {
// Element functor f over the elements of a list: thread i runs f(elements(i)). (A functor,
// not a lambda: CUDA takes no extended lambda in a class's private member.)
template <class Functor>
struct ListedElements {
  Functor f;
  Kokkos::View<const int*> elements;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const { f(elements(i)); }
};

// Whether element e has a node flagged in `node_flags`.
struct TouchesFlaggedNode {
  Kokkos::View<const int**> element_nodes;
  Kokkos::View<const int*> node_flags;
  KOKKOS_INLINE_FUNCTION bool operator()(const int e) const {
    for (int a = 0; a < static_cast<int>(element_nodes.extent(1)); ++a)
      if (node_flags(element_nodes(e, a))) return true;
    return false;
  }
};

// The elements with a node flagged in `node_flags`, in ascending order.
template <class ExecSpace>
Kokkos::View<int*> elements_with_flagged_node(const Kokkos::View<const int**>& element_nodes,
                                              const Kokkos::View<const int*>& node_flags,
                                              const Kokkos::View<int*>& buffer) {
  const int elements = static_cast<int>(element_nodes.extent(0));
  const TouchesFlaggedNode touches{element_nodes, node_flags};
  int count = 0;
  Kokkos::parallel_reduce(
      "rouleau::FluidOperator::subscale_region::count", Kokkos::RangePolicy<ExecSpace>(0, elements),
      KOKKOS_LAMBDA(const int e, int& sum) { sum += touches(e) ? 1 : 0; }, count);
  const Kokkos::View<int*> list = Kokkos::subview(buffer, std::make_pair(0, count));
  Kokkos::parallel_scan(
      "rouleau::FluidOperator::subscale_region::list", Kokkos::RangePolicy<ExecSpace>(0, elements),
      KOKKOS_LAMBDA(const int e, int& offset, const bool final) {
        if (!touches(e)) return;
        if (final) list(offset) = e;
        ++offset;
      });
  return list;
}

// node_flags(n) = 1 for every node of the listed elements.
template <class ExecSpace>
void flag_element_nodes(const Kokkos::View<const int**>& element_nodes, const Kokkos::View<const int*>& elements,
                        const Kokkos::View<int*>& node_flags) {
  const int per_element = static_cast<int>(element_nodes.extent(1));
  Kokkos::parallel_for(
      "rouleau::FluidOperator::subscale_region::flag_nodes", Kokkos::RangePolicy<ExecSpace>(0, elements.extent(0)),
      KOKKOS_LAMBDA(const int i) {
        for (int a = 0; a < per_element; ++a) node_flags(element_nodes(elements(i), a)) = 1;  // same value: no race
      });
}
}  // namespace

template <class ExecSpace>
SubscaleRegion BasicFluidOperator<ExecSpace>::subscale_region_around(const Kokkos::View<const int*>& nodes) const {
  if (node_sums_ && node_sums_->overlaps())
    throw std::logic_error("rouleau::FluidOperator::subscale_region_around: the mesh spans ranks");
  ProfilingRegion region("rouleau::FluidOperator::subscale_region_around");
  const Kokkos::View<const int**> element_nodes = mesh_.element_dof_nodes;
  // Persistent buffers (this runs every step): the node flags and the two element lists.
  if (region_node_flags_.extent(0) == 0) {
    region_node_flags_ = Kokkos::View<int*>("rouleau::FluidOperator::subscale_region::node_flags", mesh_.num_dof_nodes);
    region_elements_ = Kokkos::View<int*>("rouleau::FluidOperator::subscale_elements", mesh_.num_elements);
    region_gradient_elements_ =
        Kokkos::View<int*>("rouleau::FluidOperator::subscale_gradient_elements", mesh_.num_elements);
  }
  const Kokkos::View<int*> flags = region_node_flags_;
  Kokkos::deep_copy(flags, 0);
  Kokkos::parallel_for(
      "rouleau::FluidOperator::subscale_region::flag_support", Kokkos::RangePolicy<ExecSpace>(0, nodes.extent(0)),
      KOKKOS_LAMBDA(const int i) { flags(nodes(i)) = 1; });
  SubscaleRegion subset;
  subset.restricted = true;
  subset.elements = elements_with_flagged_node<ExecSpace>(element_nodes, flags, region_elements_);
  // Always, even when the coefficients set now have no viscous reconstruction: a solve's
  // coefficients are set when it starts, after this (at a run's first step they are not
  // set yet).
  flag_element_nodes<ExecSpace>(element_nodes, subset.elements, flags);
  subset.gradient_elements = elements_with_flagged_node<ExecSpace>(element_nodes, flags, region_gradient_elements_);
  return subset;
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::load_stabilization(const ConstVector& frozen, const ConstVector& load,
                                                       const Vector& result) const {
  ProfilingRegion region("rouleau::FluidOperator::load_stabilization");
  Scatter& scatter = zeroed_scatter(unknowns_scatter_, result.extent(0), "rouleau::FluidOperator::unknowns_scatter");
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidLoadStabilizationFunctor<decltype(element), Scatter> f{element_data(), frozen, load, lumped_mass_, scatter};
    for_each_element("rouleau::FluidOperator::load_stabilization", f, scatter, result);
  });
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::jacobian_action(const ConstVector& state, const ConstVector& direction,
                                                    const Vector& result) const {
  if (coefficients_.viscous_reconstruction) project_gradient(state, state_gradient_);
  jacobian_action(state, state_gradient_, direction, result);
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::jacobian_action(const ConstVector& state, const ConstVector& state_gradient,
                                                    const ConstVector& direction, const Vector& result) const {
  ProfilingRegion region("rouleau::FluidOperator::jacobian_action");
  if (coefficients_.viscous_reconstruction) project_gradient(direction, direction_gradient_);
  Scatter& scatter = zeroed_scatter(unknowns_scatter_, result.extent(0), "rouleau::FluidOperator::unknowns_scatter");
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidJacobianActionFunctor<decltype(element), Scatter> f{
        element_data(), state, direction, history_, body_force_, state_gradient, direction_gradient_, scatter};
    for_each_element("rouleau::FluidOperator::jacobian_action", f, scatter, result);
  });
  apply_dirichlet_rows<ExecSpace>(dirichlet_dofs_, dirichlet_values_, state, direction, false, result);
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::linear_action(const ConstVector& direction, const Vector& result) const {
  ProfilingRegion region("rouleau::FluidOperator::linear_action");
  if (coefficients_.convection)
    throw std::logic_error("rouleau::FluidOperator::linear_action: the residual is not affine with convection on");
  if (uses_stencil()) {
    await_copies();  // the stencil reads every node, copies included
    stencil_.apply(coefficients_, direction, result);
    apply_dirichlet_rows<ExecSpace>(dirichlet_dofs_, dirichlet_values_, direction, direction, false, result);
    return;
  }
  Scatter& scatter = zeroed_scatter(unknowns_scatter_, result.extent(0), "rouleau::FluidOperator::unknowns_scatter");
  if (coefficients_.viscous_reconstruction) project_gradient(direction, direction_gradient_);
  const ConstVector none;
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidResidualFunctor<decltype(element), Scatter> f{
        element_data(), direction, direction, none, none, direction_gradient_, scatter};
    for_each_element("rouleau::FluidOperator::linear_action", f, scatter, result);
  });
  apply_dirichlet_rows<ExecSpace>(dirichlet_dofs_, dirichlet_values_, direction, direction, false, result);
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::diagonal_blocks(const ConstVector& state, const Vector& blocks) const {
  ProfilingRegion region("rouleau::FluidOperator::diagonal_blocks");
  if (coefficients_.viscous_reconstruction) project_gradient(state, state_gradient_);
  Scatter& scatter = zeroed_scatter(blocks_scatter_, blocks.extent(0), "rouleau::FluidOperator::blocks_scatter");
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidElementJacobianFunctor<decltype(element), JacobianSink::diagonal_blocks, Scatter> f{
        element_data(), state, history_, body_force_, state_gradient_, scatter, {}, {}, {}, {}, {}};
    for_each_element("rouleau::FluidOperator::diagonal_blocks", f, scatter, blocks);
  });
  // A constrained row is the identity row.
  auto dofs = dirichlet_dofs_;
  Kokkos::parallel_for(
      "rouleau::FluidOperator::dirichlet_blocks", Kokkos::RangePolicy<ExecSpace>(0, dofs.extent(0)),
      KOKKOS_LAMBDA(const int k) {
        const int node = dofs(k) / 4, i = dofs(k) % 4;
        for (int j = 0; j < 4; ++j) blocks(16 * node + 4 * i + j) = i == j ? 1.0 : 0.0;
      });
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::element_matrices(const ConstVector& state, const Kokkos::View<double***>& matrices) const {
  await_copies();
  if (coefficients_.viscous_reconstruction) project_gradient(state, state_gradient_);
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidElementJacobianFunctor<decltype(element), JacobianSink::element_matrices, Scatter> f{
        element_data(), state, history_, body_force_, state_gradient_, {}, matrices, {}, {}, {}, {}};
    Kokkos::parallel_for("rouleau::FluidOperator::element_matrices",
                         Kokkos::RangePolicy<ExecSpace>(0, mesh_.num_elements), f);
  });
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::assemble_jacobian(const ConstVector& state, const BlockMatrixGraph& graph,
                                      const Vector& values) const {
  ProfilingRegion region("rouleau::FluidOperator::assemble_jacobian");
  await_copies();
  if (coefficients_.viscous_reconstruction) project_gradient(state, state_gradient_);
  Kokkos::deep_copy(values, 0.0);
  if (color_offsets_.empty()) color_elements();
  visit_fluid_element(mesh_.element_type, [&](auto element) {
    FluidElementJacobianFunctor<decltype(element), JacobianSink::crs, Scatter> f{
        element_data(), state, history_, body_force_, state_gradient_, {}, {},
        graph.row_map,  graph.node_offsets, graph.node_neighbors, values, colored_elements_};
    for (std::size_t color = 0; color + 1 < color_offsets_.size(); ++color)
      Kokkos::parallel_for("rouleau::FluidOperator::assemble_jacobian",
                           Kokkos::RangePolicy<ExecSpace, JacobianColorTag>(color_offsets_[color],
                                                                             color_offsets_[color + 1]),
                           f);
  });
  // A constrained row is the identity row.
  set_identity_rows<ExecSpace>(graph, dirichlet_dofs_, values);
}

// Greedy colouring in element order: each element takes the first colour none of its
// dof nodes has met yet (8 colours on a structured box of hexahedra, 20-30 on tetrahedra).
template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::color_elements() const {
  auto nodes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh_.element_dof_nodes);
  const int per_element = static_cast<int>(nodes.extent(1));
  std::vector<std::uint64_t> node_colors(mesh_.num_dof_nodes, 0);  // bit c: colour c used at the node
  std::vector<std::vector<int>> by_color;
  for (int e = 0; e < mesh_.num_elements; ++e) {
    std::uint64_t used = 0;
    for (int a = 0; a < per_element; ++a) used |= node_colors[nodes(e, a)];
    int color = 0;
    while (color < 64 && (used >> color) & 1u) ++color;
    if (color == 64) throw std::runtime_error("rouleau::FluidOperator: more than 64 element colours");
    for (int a = 0; a < per_element; ++a) node_colors[nodes(e, a)] |= std::uint64_t(1) << color;
    if (static_cast<int>(by_color.size()) <= color) by_color.resize(color + 1);
    by_color[color].push_back(e);
  }
  colored_elements_ = Kokkos::View<int*>("rouleau::FluidOperator::colored_elements", mesh_.num_elements);
  auto host = Kokkos::create_mirror_view(colored_elements_);
  color_offsets_.assign(1, 0);
  for (const auto& elements : by_color) {
    for (std::size_t i = 0; i < elements.size(); ++i) host(color_offsets_.back() + static_cast<int>(i)) = elements[i];
    color_offsets_.push_back(color_offsets_.back() + static_cast<int>(elements.size()));
  }
  Kokkos::deep_copy(colored_elements_, host);
}

// Runs the element functor `f` over every element and gathers its scatter buffer into
// `target`, completed across ranks when there are ranks: then the boundary elements come
// first, and their sums travel while the interior elements are summed (the protocol in
// fluid/element_sum_exchange.hpp).
template <class ExecSpace>
template <class Functor>
void BasicFluidOperator<ExecSpace>::for_each_listed_element(const char* label, const Functor& f,
                                                            const Kokkos::View<const int*>& elements,
                                                            const Scatter& scatter, const Vector& target) const {
  if (node_sums_ && node_sums_->overlaps())
    throw std::logic_error("rouleau::FluidOperator::for_each_listed_element: the mesh spans ranks");
  await_copies();
  Kokkos::parallel_for(label, Kokkos::RangePolicy<ExecSpace>(0, elements.extent(0)),
                       ListedElements<Functor>{f, elements});
  gather_into(target, scatter);
  complete_node_sums(target);
}

template <class ExecSpace>
template <class Functor>
void BasicFluidOperator<ExecSpace>::for_each_element(const char* label, const Functor& f, const Scatter& scatter,
                                                     const Vector& target) const {
  const int elements = mesh_.num_elements;
  if (!node_sums_ || !node_sums_->overlaps()) {
    await_copies();
    Kokkos::parallel_for(label, Kokkos::RangePolicy<ExecSpace>(0, elements), f);
    gather_into(target, scatter);
    complete_node_sums(target);
    return;
  }
  const int components = static_cast<int>(target.extent(0)) / mesh_.num_dof_nodes;
  const int boundary = node_sums_->boundary_elements();
  const auto run = [&](int begin, int end) {
    Kokkos::parallel_for(label, Kokkos::RangePolicy<ExecSpace>(begin, end), f);
  };
  // interior [boundary, elements): a third before the boundary when the input's copies travel
  const int first = boundary + (node_sums_->copies_in_flight() ? (elements - boundary) / 3 : 0);
  const int second = first + (elements - first) / 2;
  run(boundary, first);
  node_sums_->await_copies();
  run(0, boundary);
  gather_into(target, scatter);  // final at the shared nodes: no interior element reaches them
  node_sums_->start(target, components);
  Scatter interior = scatter;  // the same buffer, emptied for the rest of the interior
  interior.reset();
  run(first, second);
  node_sums_->advance(target, components);
  run(second, elements);
  node_sums_->finish(target, components);
  add_into(target, scatter);  // zero at the shared nodes
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::await_copies() const {
  if (node_sums_) node_sums_->await_copies();
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::start_filling_copies(const Vector& input) const {
  if (node_sums_) node_sums_->start_copies(input);
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::complete_node_sums(const Vector& target) const {
  if (node_sums_) node_sums_->complete(target, static_cast<int>(target.extent(0)) / mesh_.num_dof_nodes);
}

template <class ExecSpace>
void BasicFluidOperator<ExecSpace>::set_node_sums(const ElementSumExchange* sums) {
  if (sums && (sums->boundary_elements() < 0 || sums->boundary_elements() > mesh_.num_elements))
    throw std::logic_error("rouleau::FluidOperator::set_node_sums: " + std::to_string(sums->boundary_elements()) +
                           " boundary elements on a mesh of " + std::to_string(mesh_.num_elements));
  node_sums_ = sums;
  complete_node_sums(lumped_mass_);  // the lumped mass summed in the constructor, rank-local so far
}

// A persistent scatter buffer of `size` entries, zeroed: allocated on first use (or when
// the size changes), so the element loops allocate nothing per call.
template <class ExecSpace>
typename BasicFluidOperator<ExecSpace>::Scatter& BasicFluidOperator<ExecSpace>::zeroed_scatter(
    Scatter& buffer, std::size_t size, const char* label) const {
  if (!buffer.is_allocated() || buffer.subview().extent(0) != size)
    buffer = Scatter(label, size);  // constructed zeroed
  else
    buffer.reset();
  return buffer;
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicFluidOperator)

}  // namespace rouleau
