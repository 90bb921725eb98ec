#pragma once
// The RKPM transfer between the fixed fluid mesh and the moving solid points (paper eqs.
// 6, 15, 16; kernels/rkpm.hpp): setup (the fluid nodes in each point's support, found
// through bins of the fluid nodes built once, and the shape functions, corrected where
// the plain window does not reproduce linear fields) apart from apply: interpolation, a
// pure gather, and spreading, its exact transpose through a ScatterView, so that
// ⟨I u, F⟩ = ⟨u, S F⟩: the power the cells put into the fluid is the power it takes back.
#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>
#include <stdexcept>
#include <string>

#include "kernels/point_bins.hpp"
#include "kernels/rkpm.hpp"
#include "mesh/fluid_mesh.hpp"

namespace rouleau {

// A point with no fluid node in its support: it has left the fluid domain. Names how
// many there are and the first (lowest index), so a caller can say whose point it is.
class PointsOutsideFluidError : public std::runtime_error {
 public:
  PointsOutsideFluidError(int count, int first_point)
      : std::runtime_error("rouleau::RkpmCoupler: " + std::to_string(count) +
                           " solid points have no fluid node in their support (outside the fluid domain), the "
                           "first is point " + std::to_string(first_point)),
        count_(count),
        first_point_(first_point) {}
  int count() const { return count_; }
  int first_point() const { return first_point_; }

 private:
  int count_, first_point_;
};

template <class ExecSpace>
class BasicRkpmCoupler {
 public:
  using PointVectors = Kokkos::View<double* [3]>;

  // Supports a_Jd = support_factor × the largest extent along d of the elements at dof
  // node J (2 elements by default). Periodic directions wrap (minimum image).
  explicit BasicRkpmCoupler(const FluidMesh& mesh, double support_factor = 2.0);

  // Finds the supports of `points` (point, 3) [μm] and computes their shape functions.
  // Throws PointsOutsideFluidError when a point has no fluid node in its support (it is
  // outside the fluid domain).
  void update(const Kokkos::View<const double* [3]>& points);
  // From the next update() on, rows only for the points p with active(p) ≠ 0 (a rank's
  // cells and those its Morse pairs reach): the others get empty rows, so
  // interpolation gives them zero and spreading takes nothing from them, and only the
  // active points are checked for leaving the fluid. An empty view: every point (the
  // default).
  // `counted` (empty: every active point) marks the points whose corrections
  // corrected_points() counts: a rank's own cells, so that the ranks' counts sum to one
  // rank's.
  void restrict_rows(const Kokkos::View<const int*>& active, const Kokkos::View<const int*>& counted = {}) {
    active_points_ = active;
    counted_points_ = counted;
  }

  // values(p, c) = Σ_J Φ_J(x_p) nodal(stride · J + c), c = 0, 1, 2.
  void interpolate(const Kokkos::View<const double*>& nodal, int stride, const PointVectors& values) const;
  // nodal(stride · J + c) += Σ_p Φ_J(x_p) forces(p, c): the transpose of interpolate.
  void spread(const PointVectors& forces, const Kokkos::View<double*>& nodal, int stride) const;

  int num_points() const { return num_points_; }
  // The CSR rows: the dof nodes of each point's support and their shape functions.
  const Kokkos::View<int*>& offsets() const { return offsets_; }
  const Kokkos::View<int*>& nodes() const { return nodes_; }
  const Kokkos::View<double*>& shape_functions() const { return shape_functions_; }
  // The dof nodes in any point's support at the last update, ascending, each once: the
  // only fluid values interpolation reads and the only ones spreading writes. A view of a
  // buffer the next call overwrites.
  Kokkos::View<int*> support_nodes() const;
  // How many points (of those counted, restrict_rows) needed the linear correction at the
  // last update.
  int corrected_points() const { return corrected_points_; }
  // Forces the correction everywhere (tests: both paths agree where both apply).
  void always_correct(bool yes) { always_correct_ = yes; }

 private:
  int num_dof_nodes_ = 0, num_points_ = 0, corrected_points_ = 0;
  bool always_correct_ = false;
  Kokkos::View<double* [3]> node_position_;  // dof node positions [μm]
  Kokkos::View<double* [3]> node_support_;   // a_Jd [μm]
  BinnedPoints<typename ExecSpace::memory_space> node_bins_;  // the dof nodes, binned once
  Kokkos::View<int* [3], typename ExecSpace::memory_space> bin_depth_;  // each bin's search depth
  Kokkos::View<int*> offsets_, nodes_;
  Kokkos::View<const int*> active_points_, counted_points_;  // restrict_rows()
  Kokkos::View<double*> shape_functions_;
  // Spreading's persistent buffers (per-thread copies on CPUs, the atomic target on GPUs).
  using Scatter = Kokkos::Experimental::ScatterView<double*, typename Kokkos::View<double*>::array_layout,
                                                    typename ExecSpace::device_type>;
  mutable Kokkos::View<double*> spread_sum_;
  mutable Kokkos::View<int*> in_support_, support_nodes_;  // support_nodes()
  mutable Scatter spread_scatter_;

  // The shape functions' rows (count_only: their lengths) at `points`.
  void fill_rows(const Kokkos::View<const double* [3]>& points, bool count_only);
};

using RkpmCoupler = BasicRkpmCoupler<Kokkos::DefaultExecutionSpace>;

extern template class BasicRkpmCoupler<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
