#pragma once
// The Morse interaction between the surfaces of different cells (paper eqs. 3, 4, 11) on
// the device: the surface points (the outer-surface nodes with their reference area
// weights, or Gauss points of the outer-surface triangles: cells/surface_quadrature.hpp),
// their neighbour list with a skin (cells/surface_neighbor_list.hpp), the pair forces and
// the pairs' stiffness.
#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>
#include <optional>
#include <vector>

#include "cells/cell_population.hpp"
#include "cells/surface_neighbor_list.hpp"
#include "cells/surface_quadrature.hpp"
#include "kernels/morse.hpp"
#include "kernels/surface_neighbors.hpp"

namespace rouleau {

template <class ExecSpace>
class BasicSurfaceInteraction {
 public:
  using Population = BasicCellPopulation<ExecSpace>;
  using PointVectors = Kokkos::View<double* [3]>;

  // `cell_kind[c]`: the kind index of cell c; `potentials[a * num_kinds + b]`: the law
  // between kinds a and b (symmetric). `skin` [μm] > 0. `half_list` chooses the pair loop
  // (the half list is 1.3–1.9× faster on CPU threads, bench/kernels.md), `quadrature` the
  // surface points.
  BasicSurfaceInteraction(const Population& cells, const std::vector<int>& cell_kind, int num_kinds,
                          const std::vector<MorsePotential>& potentials, double skin, bool half_list = true,
                          SurfaceQuadrature quadrature = SurfaceQuadrature::nodes);

  // forces() = the interaction forces on the surface points at the cells' current
  // positions (rebuilding the list first when it must).
  void compute_forces();
  // The same, returning the interaction energy Σ_pairs w_i w_j φ(r_ij) [pN·μm].
  double compute_forces_and_energy();

  int num_points() const { return static_cast<int>(point_weight_.extent(0)); }
  // The surface points: their positions (at the last gather), cells, area weights [μm²]
  // and the forces on them [pN]; point p sits at Σ_k point_shape(p, k) x(point_nodes(p, k)).
  const PointVectors& point_positions() const { return point_positions_; }
  const Kokkos::View<int*>& point_cell() const { return point_cell_; }
  const Kokkos::View<double*>& point_weight() const { return point_weight_; }
  const Kokkos::View<int* [3]>& point_nodes() const { return point_nodes_; }
  const Kokkos::View<double* [3]>& point_shape() const { return point_shape_; }
  const PointVectors& forces() const { return forces_; }
  // point_positions() from the cells' current node positions (compute_forces() does it).
  void gather_point_positions();
  // node_forces(n) = the interaction force on node n of the population (zero off the
  // outer surfaces), from the last compute_forces().
  void copy_forces_to_nodes(const PointVectors& node_forces) const;
  // The interaction's stiffness K = ∂F/∂x about the current positions, for the
  // semi-implicit coupling (kernels/morse_stiffness.hpp): gathers the points, rebuilds the
  // list when it is stale, and finds the coefficients of every list pair (one exponential
  // per pair, as a force evaluation costs).
  void linearize();
  // node_force_changes(n) = (K δx)_n [pN] for the node moves δx = node_displacements [μm],
  // exactly (the pairs' Hessian blocks, no difference), about the positions of the last
  // linearize() (even if the list was rebuilt since); zero off the outer surfaces. Costs a
  // stream over the pairs in range, no exponential.
  void force_change(const PointVectors& node_displacements, const PointVectors& node_force_changes) const;
  // The pairs within the cut-off at the last linearize() (the list entries less the skin's).
  int linearized_pairs() const { return linearized_pairs_; }
  // The list: CSR rows per surface point (columns are surface points).
  const Kokkos::View<int*>& neighbor_offsets() const { return list_->offsets(); }
  const Kokkos::View<int*>& neighbors() const { return list_->neighbors(); }
  int num_list_entries() const { return list_->num_entries(); }
  int rebuild_count() const { return list_->build_count(); }
  // Per cell: 1 when a point of it is a row or a column of the list (the cells whose nodes
  // the pairs of this rank's rows move, share_rows), else 0; and how many times the list
  // has been built by this object (the flags change only then).
  const Kokkos::View<int*>& cells_in_list() const { return list_->cells_in_list(); }
  int list_version() const { return list_->version(); }
  // Cells that take part in pair work after the last broad phase (with shared rows: the
  // rows' cells that have a partner, and their partners).
  int active_cell_count() const { return list_->active_cell_count(); }
  double search_radius() const { return search_radius_; }

  // Checkpoints ("interaction/..." entries): the surface points' positions at the last
  // build of the list and the build count. Restoring rebuilds the list from those
  // positions, so it holds the same pairs in the same order as before the checkpoint (the
  // pair sums then repeat bit for bit); the cells' positions must be restored first.
  void save_state(CheckpointData& data) const;
  void restore_state(const CheckpointData& data);

  // Whether some point moved more than skin/2 since the last build (or none was made).
  bool list_is_stale() const;
  // Rebuilds the broad phase, the bins and the list at the current positions
  // (compute_forces() calls it when the list is stale).
  void rebuild();

  // This rank's share of the pair work when the cells are on every rank: the
  // list's rows are the points of `cells` alone (their columns any point), so the forces,
  // the energy and the stiffness are those of the pairs rooted at them, and the shares of
  // all ranks sum to the whole; a half list is then balanced (kernels/surface_neighbors.hpp).
  // The next force evaluation builds the list anew. Every cell by default. Throws
  // std::invalid_argument on a cell out of range.
  void share_rows(const std::vector<int>& cells);

 private:
  template <class Tag>
  double run_pair_kernel(const char* label);

  const Population& cells_;
  int num_kinds_;
  double skin_, max_cutoff_, search_radius_;
  bool half_list_;
  Kokkos::View<MorsePotential**> potentials_;
  Kokkos::View<int* [3]> point_nodes_;
  Kokkos::View<double* [3]> point_shape_;
  Kokkos::View<int*> point_cell_, point_kind_;
  Kokkos::View<double*> point_weight_;
  PointVectors point_positions_;
  PointVectors forces_;
  std::optional<BasicSurfaceNeighborList<ExecSpace>> list_;  // made once the points are known
  using Scatter = Kokkos::Experimental::ScatterView<double* [3], typename PointVectors::array_layout,
                                                    typename ExecSpace::device_type>;
  Scatter force_scatter_;
  mutable Scatter node_force_scatter_;  // point forces summed into the nodes
  // The linearization: the pairs within the cut-off (CSR, its own: a later list rebuild
  // leaves it whole) with their (a, b), and the points' positions then; none before the
  // first linearize() and after restore_state().
  Kokkos::View<int*> pair_offsets_, pair_neighbors_;
  Kokkos::View<double* [2]> pair_coefficients_;
  PointVectors linearized_positions_;
  bool linearized_ = false;
  int linearized_pairs_ = 0;
  mutable PointVectors point_displacements_, point_force_changes_;
  mutable Scatter change_scatter_;
};

using SurfaceInteraction = BasicSurfaceInteraction<Kokkos::DefaultExecutionSpace>;

extern template class BasicSurfaceInteraction<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
