#pragma once
// All cells of a scene on the device: their tetrahedral meshes concatenated, reference
// data computed once (total-Lagrangian), current positions and velocities, the elastic
// internal forces (neo-Hookean, optionally strain-hardening, kernels/neo_hookean.hpp;
// plus the optional global area and volume constraints of each cell,
// kernels/global_constraints.hpp),
// and per-cell measures from the outer surfaces.
#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/cell_mesh.hpp"
#include "io/checkpoint_file.hpp"
#include "io/xdmf_writer.hpp"
#include "kernels/global_constraints.hpp"
#include "kernels/neo_hookean.hpp"

namespace rouleau {

// One cell to place: its mesh in the body frame, x_world = center + rotation · x_body,
// its material and its area and volume moduli.
struct PlacedCell {
  const CellMesh* mesh = nullptr;
  std::array<std::array<double, 3>, 3> rotation{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  std::array<double, 3> center{0.0, 0.0, 0.0};  // [μm]
  NeoHookeanMaterial material;
  // k_A of the global area constraint E_A = k_A (A − A0)² / (2 A0) on the outer surface
  // [pN/μm]; 0 = off (the paper's law).
  double area_modulus = 0.0;
  // k_V of the global volume constraint E_V = k_V (V − V0)² / (2 V0) on the volume the
  // outer surface encloses [Pa]; 0 = off (the paper's law).
  double volume_modulus = 0.0;
  int kind = 0;  // index of the cell's kind (for output)
};

// A cell's measures from its outer surface (the cavity of a shell included).
struct CellMeasures {
  double volume = 0.0;                  // enclosed volume [μm³]
  double area = 0.0;                    // outer surface area [μm²]
  std::array<double, 3> centroid{};     // volume centroid [μm]
};

template <class ExecSpace>
class BasicCellPopulation {
 public:
  using NodeVectors = Kokkos::View<double* [3]>;
  using ConstNodeVectors = Kokkos::View<const double* [3]>;
  using Scatter = Kokkos::Experimental::ScatterView<double* [3], typename NodeVectors::array_layout,
                                                    typename ExecSpace::device_type>;
  using CellSumsScatter = Kokkos::Experimental::ScatterView<double* [5], typename NodeVectors::array_layout,
                                                            typename ExecSpace::device_type>;

  // Places the cells (reference = current configuration at rest, velocities zero).
  // Throws std::invalid_argument when a mesh has an inverted or degenerate tetrahedron or
  // an area modulus is negative.
  explicit BasicCellPopulation(const std::vector<PlacedCell>& cells);

  int num_cells() const { return num_cells_; }
  int num_nodes() const { return static_cast<int>(positions_.extent(0)); }
  int num_elements() const { return static_cast<int>(element_nodes_.extent(0)); }
  int num_surface_triangles() const { return static_cast<int>(surface_triangles_.extent(0)); }

  // The state, read-only. The positions and velocities have three named writers: move()
  // (the time step), set_positions() (placing the nodes: a static solve's result, the
  // run's set_cell_positions, tests) and restore_state() (a checkpoint).
  ConstNodeVectors reference_positions() const { return reference_positions_; }
  ConstNodeVectors positions() const { return positions_; }
  ConstNodeVectors velocities() const { return velocities_; }
  ConstNodeVectors internal_forces() const { return internal_forces_; }

  // The time step's move (kernels/cell_motion.hpp): v^{n+1} = U v̂ from the scaled velocities
  // v̂ interpolated from the fluid, x^{n+1} = x^n + Δt v^{n+1}, and v^n into
  // `previous_velocities`. Returns the largest speed² [μm²/s²]
  // (MoveCellsFunctor::non_finite_speed2 when a velocity is NaN or Inf: that node stays).
  double move(const ConstNodeVectors& scaled_velocities, double velocity_scale, double dt,
              const NodeVectors& previous_velocities);
  // Places the nodes at `positions` (node, 3) [μm]: any View that Kokkos::deep_copy copies
  // into positions() (another device View, a host mirror). The velocities stay.
  template <class Positions>
  void set_positions(const Positions& positions) {
    if (positions.extent(0) != positions_.extent(0))
      throw std::invalid_argument("rouleau::CellPopulation::set_positions: " + std::to_string(positions.extent(0)) +
                                  " positions for " + std::to_string(positions_.extent(0)) + " nodes");
    Kokkos::deep_copy(positions_, positions);
  }

  // Checkpoints: the nodes' positions and velocities ("cells/..." entries). The reference
  // configuration is rebuilt from the case (the run checks the meshes' hashes). Restoring
  // throws std::runtime_error naming the entry when one is missing or of the wrong size.
  void save_state(CheckpointData& data) const;
  void restore_state(const CheckpointData& data);

  // The mesh data.
  Kokkos::View<const int* [4]> element_nodes() const { return element_nodes_; }
  Kokkos::View<const int*> element_cell() const { return element_cell_; }
  Kokkos::View<const int*> node_cell() const { return node_cell_; }
  Kokkos::View<const double* [3][3]> inverse_edge_matrix() const { return inverse_edge_matrix_; }
  Kokkos::View<const double*> reference_volume() const { return reference_volume_; }
  Kokkos::View<const int* [3]> surface_triangles() const { return surface_triangles_; }
  Kokkos::View<const int*> triangle_cell() const { return triangle_cell_; }
  // Nodal area weights of the outer surfaces in the reference configuration (zero off
  // the surface): w_n = Σ_{t ∋ n} A_t / 3 [μm²].
  Kokkos::View<const double*> surface_area_weights() const { return surface_area_weights_; }
  // First node and node count of each cell (host): cell c owns nodes
  // [cell_first_node[c], cell_first_node[c] + cell_node_count[c]).
  const std::vector<int>& cell_first_node() const { return cell_first_node_host_; }
  const std::vector<int>& cell_node_count() const { return cell_node_count_host_; }

  // internal_forces() = f, f_a = −Σ_e V0 P(F_e) ∇N_a (paper eqs. 2, 9, 10) at the
  // current positions, plus −T_c ∂A_c/∂x_a − P_c ∂V_c/∂x_a of the cells with global
  // constraints.
  void compute_internal_forces();
  // The same, returning the total elastic energy Σ_e V0 W(F_e) + E_A + E_V [pN·μm].
  double compute_internal_forces_and_energy();
  // The same forces at other `positions` (a trial configuration: the semi-implicit
  // coupling's differences, coupling/cell_stiffness.hpp) into `forces`, leaving the
  // population's own state (internal_forces(), the constraints' tensions and pressures)
  // as it is.
  void internal_forces_at(const ConstNodeVectors& positions, const NodeVectors& forces) const;
  // This rank's share of the elastic work when the cells are on every rank:
  // the two calls above then give the forces and energy of `cells` (ascending, each once)
  // alone (their elements and constraints; zero at the other cells' nodes), and the shares
  // of all ranks sum to the whole. Every cell by default. Throws std::invalid_argument on
  // a cell out of range, repeated or out of order.
  void share_work(const std::vector<int>& cells);
  // Whether share_work() was called: the forces and energies are then this rank's share.
  bool work_is_shared() const { return work_shared_; }

  // The global area and volume constraints (kernels/global_constraints.hpp): whether any
  // cell has one, A0 and V0 per cell, the tensions T_c [pN/μm] and pressures P_c [Pa] of
  // the last force evaluation (zero where off), and E_A + E_V of the last
  // compute_internal_forces_and_energy() [pN·μm].
  bool has_global_constraints() const { return global_constraints_; }
  Kokkos::View<const double*> reference_areas() const { return reference_areas_; }
  Kokkos::View<const double*> reference_volumes() const { return reference_volumes_; }
  Kokkos::View<const double*> area_tensions() const { return area_tensions_; }
  Kokkos::View<const double*> volume_pressures() const { return volume_pressures_; }
  double constraint_energy() const { return constraint_energy_; }

  // Per-cell volume, area and centroid at the current positions (a small host copy).
  std::vector<CellMeasures> measures() const { return measures_at(positions_); }
  // The same at other `positions` (node, 3) [μm] (a trial configuration).
  std::vector<CellMeasures> measures_at(const ConstNodeVectors& positions) const;

  // The element with the smallest volume ratio J = det F at the current positions
  // (kernels/state_checks.hpp): J ≤ 0 means it is inverted; a NaN position gives the
  // lowest double.
  struct CompressedElement {
    double volume_ratio = 1.0;  // J = V/V0
    int element = -1;
    int cell = -1;  // found only when the element is inverted (volume_ratio ≤ 0), else −1
  };
  CompressedElement most_compressed_element() const;
  // The cell that owns node `node` (host).
  int cell_of_node(int node) const;

  // The cells' meshes for the XDMF writer ("cells", reference coordinates, tetrahedra).
  MeshDescription mesh_description() const;
  // Host copies (node-major) of the current positions and of the nodal fields written
  // with each output step: displacement, velocity, internal force, and the cell id.
  struct HostFields {
    std::vector<double> positions, displacement, velocity, internal_force, cell_id;
  };
  void copy_fields_to_host(HostFields& fields) const;

 private:
  // Where one force evaluation writes: the forces, and the constraints' multipliers.
  struct ForceOutputs {
    NodeVectors forces;
    Kokkos::View<double*> area_tensions, volume_pressures;
    double* constraint_energy = nullptr;  // E_A + E_V, with ForcesAndEnergy
  };
  // The force kernel at `positions` launched with tag ForcesOnly or ForcesAndEnergy; returns
  // the energy (0 for ForcesOnly).
  template <class Tag>
  double run_force_kernel(const char* label, const ConstNodeVectors& positions, const ForceOutputs& outputs) const;
  // Adds the global-constraint forces at `positions` into force_scatter_ (the multipliers
  // into `outputs`); returns E_A + E_V (0 for ForcesOnly).
  template <class Tag>
  double add_global_constraint_forces(const ConstNodeVectors& positions, const ForceOutputs& outputs) const;
  // computed_elements_, computed_triangles_ and computed_cells_ for `cells`.
  void list_computed_work(const std::vector<int>& cells);
  // The surface sums (CellSurfaceSum) of every cell at `positions` into cell_sums_.
  void compute_surface_sums(const ConstNodeVectors& positions) const;

  int num_cells_ = 0;
  NodeVectors reference_positions_, positions_, velocities_, internal_forces_;
  Kokkos::View<int* [4]> element_nodes_;
  Kokkos::View<int*> element_cell_, node_cell_;
  Kokkos::View<double* [3][3]> inverse_edge_matrix_;
  Kokkos::View<double*> reference_volume_;
  Kokkos::View<NeoHookeanMaterial*> materials_;  // one per cell
  Kokkos::View<int* [3]> surface_triangles_;
  Kokkos::View<int*> triangle_cell_, cell_first_node_;
  Kokkos::View<double*> surface_area_weights_;
  Kokkos::View<double* [5]> cell_sums_;
  // Per cell: k_A, k_V, A0, V0, T_c, P_c.
  Kokkos::View<double*> area_moduli_, volume_moduli_, reference_areas_, reference_volumes_, area_tensions_,
      volume_pressures_;
  // The multipliers of internal_forces_at() (scratch: a trial configuration's).
  Kokkos::View<double*> trial_area_tensions_, trial_volume_pressures_;
  bool global_constraints_ = false;
  double constraint_energy_ = 0.0;
  NodeVectors cell_origins_;  // the point each cell's surface sums are taken from
  std::vector<int> cell_first_node_host_, cell_node_count_host_;
  // Where each cell's elements and outer-surface triangles start (and end: num_cells + 1).
  std::vector<int> cell_element_offsets_, cell_triangle_offsets_;
  // The elements, outer-surface triangles and cells whose forces this rank computes
  // (share_work; every one by default), ascending.
  Kokkos::View<int*> computed_elements_, computed_triangles_, computed_cells_;
  bool work_shared_ = false;
  // Persistent scatter buffers (per-thread copies on CPUs, the atomic target on GPUs).
  mutable Scatter force_scatter_;
  mutable CellSumsScatter cell_sums_scatter_;
};

using CellPopulation = BasicCellPopulation<Kokkos::DefaultExecutionSpace>;

extern template class BasicCellPopulation<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
