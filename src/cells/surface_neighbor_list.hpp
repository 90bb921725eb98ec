#pragma once
// The Morse interaction's neighbour list: the pairs of surface points of different cells
// closer than the search radius r = r_c + skin, as CSR rows per point, with the broad
// phase that keeps far cells out of it.
//
// The list is rebuilt only when some point has moved more than skin/2 since the last
// build (then no pair closer than r_c can be missing). A build takes each cell's bounding
// box, finds the cells whose boxes grown by r meet another's (sweep and prune along x),
// sorts those cells' points into bins of width r/2 (kernels/point_bins.hpp, searched two
// deep: the 5³ bins around a point cover (5r/2)³ = 15.6 r³ against 27 r³ for 3³ bins of
// width r) and lists, for each point, the points of other cells within r in those bins
// (kernels/surface_neighbors.hpp): count, scan, fill (kernels/csr_rows.hpp).
#include <Kokkos_Core.hpp>
#include <vector>

#include "io/checkpoint_file.hpp"
#include "kernels/point_bins.hpp"

namespace rouleau {

template <class ExecSpace>
class BasicSurfaceNeighborList {
 public:
  using PointVectors = Kokkos::View<double* [3]>;

  // The points are numbered cell by cell: cell c's are [cell_first_point[c],
  // cell_first_point[c + 1]); point_cell(p) is p's cell. `half_list`: each pair once (in
  // the row of its lower index), else once from each side.
  BasicSurfaceNeighborList(const std::vector<int>& cell_first_point, const Kokkos::View<int*>& point_cell,
                           double search_radius, double skin, bool half_list);

  // Whether some point moved more than skin/2 since the last build (or none was made).
  bool is_stale(const PointVectors& point_positions) const;
  // Builds the broad phase, the bins and the list at `point_positions`.
  void build(const PointVectors& point_positions);

  // This rank's share of the rows (see SurfaceInteraction::share_rows): the rows are the
  // points of `cells`, the columns any point; a half list is then balanced. The next
  // build() takes effect. Throws std::invalid_argument on a cell out of range.
  void share_rows(const std::vector<int>& cells);

  const Kokkos::View<int*>& offsets() const { return offsets_; }
  const Kokkos::View<int*>& neighbors() const { return neighbors_; }
  int num_entries() const { return entries_; }
  int build_count() const { return builds_; }
  // Per cell: 1 when a point of it is a row or a column of the list.
  const Kokkos::View<int*>& cells_in_list() const { return cells_in_list_; }
  // How many times this object has built the list (cells_in_list() changes only then).
  int version() const { return version_; }
  int active_cell_count() const { return active_cells_; }
  double search_radius() const { return search_radius_; }

  // Checkpoints ("interaction/..." entries): the points' positions at the last build and
  // the build count. restore_state() writes those positions into `point_positions` and
  // builds the list from them, so that it holds the same pairs in the same order as
  // before the checkpoint.
  void save_state(CheckpointData& data) const;
  void restore_state(const CheckpointData& data, const PointVectors& point_positions);

 private:
  int num_cells_, num_points_;
  double search_radius_, skin_;
  bool half_list_;
  Kokkos::View<int*> cell_first_point_device_;  // points of cell c: [first(c), first(c + 1))
  Kokkos::View<int*> point_cell_;
  PointVectors positions_at_build_;
  Kokkos::View<double* [6]> cell_boxes_;       // (cell, [lower xyz, upper xyz])
  Kokkos::View<int*> point_active_;            // 1 when the point's cell has a partner
  BinnedPoints<typename ExecSpace::memory_space> bins_;
  Kokkos::View<int*> offsets_, neighbors_;
  Kokkos::View<int*> cells_in_list_;
  Kokkos::View<int*> row_cells_;               // (cell): 1 when its points are rows (share_rows)
  std::vector<int> row_cells_host_;            // the same on the host
  bool rows_shared_ = false;
  bool built_ = false;
  int entries_ = 0, builds_ = 0, version_ = 0, active_cells_ = 0;

 public:
  // (Kernels with lambdas must be public for CUDA.)
  // The broad phase: marks point_active_ and returns the active cells' common box.
  void find_active_cells(const PointVectors& point_positions, double lower[3], double upper[3]);
  // The list's rows at `point_positions` (count_only: their lengths into offsets_).
  void fill_rows(const PointVectors& point_positions, bool count_only);
};

using SurfaceNeighborList = BasicSurfaceNeighborList<Kokkos::DefaultExecutionSpace>;

extern template class BasicSurfaceNeighborList<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
