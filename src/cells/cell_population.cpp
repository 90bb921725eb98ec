#include "cells/cell_population.hpp"

#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "kernels/cell_motion.hpp"
#include "kernels/cell_surface.hpp"
#include "kernels/over_indices.hpp"
#include "kernels/scatter_sum.hpp"
#include "kernels/state_checks.hpp"
#include "kernels/tet4.hpp"
#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"
#include "util/view_transfer.hpp"

namespace rouleau {

template <class ExecSpace>
BasicCellPopulation<ExecSpace>::BasicCellPopulation(const std::vector<PlacedCell>& cells)
    : num_cells_(static_cast<int>(cells.size())) {
  ProfilingRegion region("rouleau::CellPopulation::setup");
  std::size_t node_count = 0, element_count = 0, triangle_count = 0;
  for (const PlacedCell& cell : cells) {
    if (!cell.mesh) throw std::invalid_argument("rouleau::CellPopulation: a cell without a mesh");
    node_count += cell.mesh->nodes.size();
    element_count += cell.mesh->tetrahedra.size();
    triangle_count += cell.mesh->outer_surface.size();
  }
  reference_positions_ = NodeVectors("rouleau::CellPopulation::reference_positions", node_count);
  positions_ = NodeVectors("rouleau::CellPopulation::positions", node_count);
  velocities_ = NodeVectors("rouleau::CellPopulation::velocities", node_count);
  internal_forces_ = NodeVectors("rouleau::CellPopulation::internal_forces", node_count);
  node_cell_ = Kokkos::View<int*>("rouleau::CellPopulation::node_cell", node_count);
  element_nodes_ = Kokkos::View<int* [4]>("rouleau::CellPopulation::element_nodes", element_count);
  element_cell_ = Kokkos::View<int*>("rouleau::CellPopulation::element_cell", element_count);
  inverse_edge_matrix_ = Kokkos::View<double* [3][3]>("rouleau::CellPopulation::inverse_edge_matrix", element_count);
  reference_volume_ = Kokkos::View<double*>("rouleau::CellPopulation::reference_volume", element_count);
  materials_ = Kokkos::View<NeoHookeanMaterial*>("rouleau::CellPopulation::materials", cells.size());
  surface_triangles_ = Kokkos::View<int* [3]>("rouleau::CellPopulation::surface_triangles", triangle_count);
  triangle_cell_ = Kokkos::View<int*>("rouleau::CellPopulation::triangle_cell", triangle_count);
  cell_first_node_ = Kokkos::View<int*>("rouleau::CellPopulation::cell_first_node", cells.size());
  surface_area_weights_ = Kokkos::View<double*>("rouleau::CellPopulation::surface_area_weights", node_count);
  cell_sums_ = Kokkos::View<double* [5]>("rouleau::CellPopulation::cell_sums", cells.size());
  cell_origins_ = NodeVectors("rouleau::CellPopulation::cell_origins", cells.size());
  area_moduli_ = Kokkos::View<double*>("rouleau::CellPopulation::area_moduli", cells.size());
  volume_moduli_ = Kokkos::View<double*>("rouleau::CellPopulation::volume_moduli", cells.size());
  reference_areas_ = Kokkos::View<double*>("rouleau::CellPopulation::reference_areas", cells.size());
  reference_volumes_ = Kokkos::View<double*>("rouleau::CellPopulation::reference_volumes", cells.size());
  area_tensions_ = Kokkos::View<double*>("rouleau::CellPopulation::area_tensions", cells.size());
  volume_pressures_ = Kokkos::View<double*>("rouleau::CellPopulation::volume_pressures", cells.size());
  trial_area_tensions_ = Kokkos::View<double*>("rouleau::CellPopulation::trial_area_tensions", cells.size());
  trial_volume_pressures_ = Kokkos::View<double*>("rouleau::CellPopulation::trial_volume_pressures", cells.size());

  auto x = Kokkos::create_mirror_view(reference_positions_);
  auto node_cell = Kokkos::create_mirror_view(node_cell_);
  auto element_nodes = Kokkos::create_mirror_view(element_nodes_);
  auto element_cell = Kokkos::create_mirror_view(element_cell_);
  auto materials = Kokkos::create_mirror_view(materials_);
  auto triangles = Kokkos::create_mirror_view(surface_triangles_);
  auto triangle_cell = Kokkos::create_mirror_view(triangle_cell_);
  auto first_node = Kokkos::create_mirror_view(cell_first_node_);
  auto area_moduli = Kokkos::create_mirror_view(area_moduli_);
  auto volume_moduli = Kokkos::create_mirror_view(volume_moduli_);
  std::size_t node = 0, element = 0, triangle = 0;
  for (int c = 0; c < num_cells_; ++c) {
    const PlacedCell& cell = cells[c];
    const CellMesh& mesh = *cell.mesh;
    const int offset = static_cast<int>(node);
    cell_element_offsets_.push_back(static_cast<int>(element));
    cell_triangle_offsets_.push_back(static_cast<int>(triangle));
    first_node(c) = offset;
    cell_first_node_host_.push_back(offset);
    cell_node_count_host_.push_back(static_cast<int>(mesh.nodes.size()));
    materials(c) = cell.material;
    for (const auto& [modulus, name] : {std::pair{cell.area_modulus, "area modulus"},
                                        std::pair{cell.volume_modulus, "volume modulus"}})
      if (!(modulus >= 0.0)) {
        std::ostringstream msg;
        msg << "rouleau::CellPopulation: cell " << c << " has " << name << " " << modulus << " (must be >= 0)";
        throw std::invalid_argument(msg.str());
      }
    area_moduli(c) = cell.area_modulus;
    volume_moduli(c) = cell.volume_modulus;
    global_constraints_ = global_constraints_ || cell.area_modulus > 0.0 || cell.volume_modulus > 0.0;
    // x_world = center + R x_body
    for (const auto& p : mesh.nodes) {
      for (int i = 0; i < 3; ++i)
        x(node, i) = cell.center[i] + cell.rotation[i][0] * p[0] + cell.rotation[i][1] * p[1] + cell.rotation[i][2] * p[2];
      node_cell(node++) = c;
    }
    for (const auto& tet : mesh.tetrahedra) {
      for (int a = 0; a < 4; ++a) element_nodes(element, a) = offset + tet[a];
      element_cell(element++) = c;
    }
    for (const auto& tri : mesh.outer_surface) {
      for (int k = 0; k < 3; ++k) triangles(triangle, k) = offset + tri[k];
      triangle_cell(triangle++) = c;
    }
  }
  cell_element_offsets_.push_back(static_cast<int>(element));
  cell_triangle_offsets_.push_back(static_cast<int>(triangle));
  std::vector<int> every_cell(num_cells_);
  for (int c = 0; c < num_cells_; ++c) every_cell[c] = c;
  list_computed_work(every_cell);
  Kokkos::deep_copy(reference_positions_, x);
  Kokkos::deep_copy(positions_, x);
  Kokkos::deep_copy(node_cell_, node_cell);
  Kokkos::deep_copy(element_nodes_, element_nodes);
  Kokkos::deep_copy(element_cell_, element_cell);
  Kokkos::deep_copy(materials_, materials);
  Kokkos::deep_copy(surface_triangles_, triangles);
  Kokkos::deep_copy(triangle_cell_, triangle_cell);
  Kokkos::deep_copy(cell_first_node_, first_node);
  Kokkos::deep_copy(area_moduli_, area_moduli);
  Kokkos::deep_copy(volume_moduli_, volume_moduli);

  // Reference data of the tetrahedra, once (total-Lagrangian).
  Tet4ReferenceFunctor<NodeVectors, Kokkos::View<int* [4]>, Kokkos::View<double* [3][3]>, Kokkos::View<double*>>
      reference{reference_positions_, element_nodes_, inverse_edge_matrix_, reference_volume_};
  int degenerate = 0;
  Kokkos::parallel_reduce("rouleau::CellPopulation::reference_data",
                          Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(element_count)), reference, degenerate);
  if (degenerate > 0) {
    std::ostringstream msg;
    msg << "rouleau::CellPopulation: " << degenerate << " of " << element_count
        << " cell tetrahedra are inverted or degenerate (reference volume <= 0)";
    throw std::invalid_argument(msg.str());
  }

  // Nodal area weights of the outer surfaces, on the reference configuration.
  using WeightScatter = Kokkos::Experimental::ScatterView<double*, typename Kokkos::View<double*>::array_layout,
                                                          typename ExecSpace::device_type>;
  WeightScatter weights("rouleau::CellPopulation::area_weight_scatter", node_count);
  SurfaceAreaWeightsFunctor<WeightScatter> area_weights{reference_positions_, surface_triangles_, weights};
  Kokkos::parallel_for("rouleau::CellPopulation::surface_area_weights",
                       Kokkos::RangePolicy<ExecSpace>(0, static_cast<int>(triangle_count)), area_weights);
  gather_into(surface_area_weights_, weights);

  force_scatter_ = Scatter("rouleau::CellPopulation::force_scatter", node_count);
  cell_sums_scatter_ = CellSumsScatter("rouleau::CellPopulation::cell_sums_scatter", cells.size());

  // Reference areas A0_c and volumes V0_c of the outer surfaces (global constraints).
  compute_surface_sums(reference_positions_);
  Kokkos::deep_copy(reference_areas_, Kokkos::subview(cell_sums_, Kokkos::ALL, int(surface_area)));
  Kokkos::deep_copy(reference_volumes_, Kokkos::subview(cell_sums_, Kokkos::ALL, int(enclosed_volume)));
}

template <class ExecSpace>
void BasicCellPopulation<ExecSpace>::compute_surface_sums(const ConstNodeVectors& positions) const {
  cell_sums_scatter_.reset();
  CellSurfaceSumsFunctor<CellSumsScatter> sums{positions, surface_triangles_, triangle_cell_, cell_first_node_,
                                               cell_sums_scatter_};
  Kokkos::parallel_for("rouleau::CellPopulation::surface_sums",
                       Kokkos::RangePolicy<ExecSpace>(0, num_surface_triangles()), sums);
  gather_into(cell_sums_, cell_sums_scatter_);
}

template <class ExecSpace>
template <class Tag>
double BasicCellPopulation<ExecSpace>::run_force_kernel(const char* label, const ConstNodeVectors& positions,
                                                        const ForceOutputs& outputs) const {
  ProfilingRegion region("rouleau::CellPopulation::internal_forces");
  force_scatter_.reset();
  NeoHookeanForceFunctor<Scatter> forces{positions,     element_nodes_, inverse_edge_matrix_, reference_volume_,
                                         element_cell_, materials_,     force_scatter_};
  // This rank's cells' elements (share_work; every element by default).
  const auto elements = over_indices(forces, computed_elements_);
  const Kokkos::RangePolicy<ExecSpace, Tag> policy(0, computed_elements_.extent(0));
  double energy = 0.0;
  if constexpr (std::is_same_v<Tag, ForcesAndEnergy>)
    Kokkos::parallel_reduce(label, policy, elements, energy);
  else
    Kokkos::parallel_for(label, policy, elements);
  if (global_constraints_) energy += add_global_constraint_forces<Tag>(positions, outputs);
  gather_into(outputs.forces, force_scatter_);
  return energy;
}

template <class ExecSpace>
template <class Tag>
double BasicCellPopulation<ExecSpace>::add_global_constraint_forces(const ConstNodeVectors& positions,
                                                                    const ForceOutputs& outputs) const {
  ProfilingRegion region("rouleau::CellPopulation::global_constraints");
  // A_c and V_c, then T_c, P_c (and E_A + E_V), then f_a −= T_c ∂A_c/∂x_a + P_c ∂V_c/∂x_a.
  compute_surface_sums(positions);
  GlobalConstraintFunctor multipliers{cell_sums_,     reference_areas_,       reference_volumes_,
                                      area_moduli_,   volume_moduli_,         outputs.area_tensions,
                                      outputs.volume_pressures};
  const Kokkos::RangePolicy<ExecSpace, Tag> cells(0, computed_cells_.extent(0));
  const auto cell_multipliers = over_indices(multipliers, computed_cells_);
  double energy = 0.0;
  if constexpr (std::is_same_v<Tag, ForcesAndEnergy>) {
    Kokkos::parallel_reduce("rouleau::CellPopulation::constraint_multipliers_and_energy", cells, cell_multipliers,
                            energy);
    if (outputs.constraint_energy) *outputs.constraint_energy = energy;
  } else {
    Kokkos::parallel_for("rouleau::CellPopulation::constraint_multipliers", cells, cell_multipliers);
  }
  GlobalConstraintForceFunctor<Scatter> forces{positions,          surface_triangles_,      triangle_cell_,
                                               cell_first_node_,   outputs.area_tensions, outputs.volume_pressures,
                                               force_scatter_};
  Kokkos::parallel_for("rouleau::CellPopulation::global_constraint_forces",
                       Kokkos::RangePolicy<ExecSpace>(0, computed_triangles_.extent(0)),
                       over_indices(forces, computed_triangles_));
  return energy;
}

template <class ExecSpace>
void BasicCellPopulation<ExecSpace>::share_work(const std::vector<int>& cells) {
  for (std::size_t k = 0; k < cells.size(); ++k)
    if (cells[k] < 0 || cells[k] >= num_cells_ || (k > 0 && cells[k] <= cells[k - 1]))
      throw std::invalid_argument("rouleau::CellPopulation::share_work: cell " + std::to_string(cells[k]) +
                                  " at position " + std::to_string(k) + " of the share: the cells must be ascending, "
                                  "each once, in [0, " + std::to_string(num_cells_) + ")");
  list_computed_work(cells);
  work_shared_ = true;
}

template <class ExecSpace>
void BasicCellPopulation<ExecSpace>::list_computed_work(const std::vector<int>& cells) {
  std::vector<int> elements, triangles;
  for (const int c : cells) {
    for (int e = cell_element_offsets_[c]; e < cell_element_offsets_[c + 1]; ++e) elements.push_back(e);
    for (int t = cell_triangle_offsets_[c]; t < cell_triangle_offsets_[c + 1]; ++t) triangles.push_back(t);
  }
  computed_cells_ = device_copy(cells, "rouleau::CellPopulation::computed_cells");
  computed_elements_ = device_copy(elements, "rouleau::CellPopulation::computed_elements");
  computed_triangles_ = device_copy(triangles, "rouleau::CellPopulation::computed_triangles");
}

template <class ExecSpace>
void BasicCellPopulation<ExecSpace>::compute_internal_forces() {
  run_force_kernel<ForcesOnly>("rouleau::CellPopulation::internal_forces", positions_,
                               {internal_forces_, area_tensions_, volume_pressures_});
}

template <class ExecSpace>
double BasicCellPopulation<ExecSpace>::compute_internal_forces_and_energy() {
  return run_force_kernel<ForcesAndEnergy>("rouleau::CellPopulation::internal_forces_and_energy", positions_,
                                           {internal_forces_, area_tensions_, volume_pressures_, &constraint_energy_});
}

template <class ExecSpace>
void BasicCellPopulation<ExecSpace>::internal_forces_at(const ConstNodeVectors& positions,
                                                        const NodeVectors& forces) const {
  run_force_kernel<ForcesOnly>("rouleau::CellPopulation::internal_forces_at", positions,
                               {forces, trial_area_tensions_, trial_volume_pressures_});
}

template <class ExecSpace>
std::vector<CellMeasures> BasicCellPopulation<ExecSpace>::measures_at(const ConstNodeVectors& positions) const {
  ProfilingRegion region("rouleau::CellPopulation::measures");
  compute_surface_sums(positions);
  // The origins o of the sums (each cell's first node), gathered on the device.
  auto first_node = cell_first_node_;
  auto origins = cell_origins_;
  Kokkos::parallel_for(
      "rouleau::CellPopulation::cell_origins", Kokkos::RangePolicy<ExecSpace>(0, num_cells_),
      KOKKOS_LAMBDA(const int c) {
        for (int i = 0; i < 3; ++i) origins(c, i) = positions(first_node(c), i);
      });
  auto host_sums = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cell_sums_);
  auto o = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cell_origins_);
  std::vector<CellMeasures> result(num_cells_);
  for (int c = 0; c < num_cells_; ++c) {
    CellMeasures& m = result[c];
    m.volume = host_sums(c, enclosed_volume);
    m.area = host_sums(c, surface_area);
    for (int i = 0; i < 3; ++i) m.centroid[i] = o(c, i) + host_sums(c, first_moment_x + i) / m.volume;
  }
  return result;
}

template <class ExecSpace>
double BasicCellPopulation<ExecSpace>::move(const ConstNodeVectors& scaled_velocities, const double velocity_scale,
                                            const double dt, const NodeVectors& previous_velocities) {
  double largest_speed2 = 0.0;
  MoveCellsFunctor<NodeVectors> move{scaled_velocities, velocities_,    previous_velocities,
                                     positions_,        velocity_scale, dt};
  Kokkos::parallel_reduce("rouleau::CellPopulation::move", Kokkos::RangePolicy<ExecSpace>(0, num_nodes()), move,
                          Kokkos::Max<double>(largest_speed2));
  return largest_speed2;
}

template <class ExecSpace>
typename BasicCellPopulation<ExecSpace>::CompressedElement BasicCellPopulation<ExecSpace>::most_compressed_element()
    const {
  SmallestVolumeRatioFunctor::value_type smallest;
  Kokkos::parallel_reduce("rouleau::CellPopulation::most_compressed_element",
                          Kokkos::RangePolicy<ExecSpace>(0, num_elements()),
                          SmallestVolumeRatioFunctor{positions_, element_nodes_, inverse_edge_matrix_},
                          SmallestVolumeRatioFunctor::Reducer(smallest));
  CompressedElement result;
  if (smallest.loc < 0 || smallest.loc >= num_elements()) return result;  // no elements
  result.volume_ratio = smallest.val;
  result.element = smallest.loc;
  // Every step asks; only an inverted element is worth the copy of its cell from the device.
  if (result.volume_ratio <= 0.0) Kokkos::deep_copy(result.cell, Kokkos::subview(element_cell_, result.element));
  return result;
}

template <class ExecSpace>
int BasicCellPopulation<ExecSpace>::cell_of_node(const int node) const {
  for (int c = 0; c < num_cells_; ++c)
    if (node >= cell_first_node_host_[c] && node < cell_first_node_host_[c] + cell_node_count_host_[c]) return c;
  return -1;
}

template <class ExecSpace>
MeshDescription BasicCellPopulation<ExecSpace>::mesh_description() const {
  MeshDescription d;
  d.name = "cells";
  d.cell_type = CellType::tetrahedron4;
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), reference_positions_);
  auto c = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), element_nodes_);
  d.coordinates.resize(3 * x.extent(0));
  for (std::size_t n = 0; n < x.extent(0); ++n)
    for (int k = 0; k < 3; ++k) d.coordinates[3 * n + k] = x(n, k);
  d.connectivity.resize(4 * c.extent(0));
  for (std::size_t e = 0; e < c.extent(0); ++e)
    for (int a = 0; a < 4; ++a) d.connectivity[4 * e + a] = c(e, a);
  return d;
}

template <class ExecSpace>
void BasicCellPopulation<ExecSpace>::copy_fields_to_host(HostFields& fields) const {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), positions_);
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), reference_positions_);
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), velocities_);
  auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), internal_forces_);
  auto cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), node_cell_);
  const std::size_t n = x.extent(0);
  fields.positions.resize(3 * n);
  fields.displacement.resize(3 * n);
  fields.velocity.resize(3 * n);
  fields.internal_force.resize(3 * n);
  fields.cell_id.resize(n);
  for (std::size_t a = 0; a < n; ++a) {
    for (int i = 0; i < 3; ++i) {
      fields.positions[3 * a + i] = x(a, i);
      fields.displacement[3 * a + i] = x(a, i) - x0(a, i);
      fields.velocity[3 * a + i] = v(a, i);
      fields.internal_force[3 * a + i] = f(a, i);
    }
    fields.cell_id[a] = cell(a);
  }
}

template <class ExecSpace>
void BasicCellPopulation<ExecSpace>::save_state(CheckpointData& data) const {
  data.reals["cells/positions"] = to_flat_vector(positions_);
  data.reals["cells/velocities"] = to_flat_vector(velocities_);
}

template <class ExecSpace>
void BasicCellPopulation<ExecSpace>::restore_state(const CheckpointData& data) {
  const long long size = 3LL * num_nodes();
  from_flat_vector(data.real("cells/positions", size), positions_, "cells/positions");
  from_flat_vector(data.real("cells/velocities", size), velocities_, "cells/velocities");
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicCellPopulation)

}  // namespace rouleau
