#pragma once
// The transfer between the cells' nodes and the fluid (paper eqs. 6, 15, 16): the RKPM
// interpolation at the nodes and spreading, its transpose; with coupling.shell_midsurface,
// hollow shells' nodes take the normal part of their velocity at their membrane's
// mid-surface points and spread the normal part of their force from there
// (kernels/shell_midsurface.hpp). Either way ⟨I u, F⟩ = ⟨u, S F⟩ to round-off.
#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>
#include <memory>

#include "cells/cells_from_case.hpp"
#include "coupling/rkpm_coupler.hpp"

namespace rouleau {

class CellFluidTransfer {
 public:
  using NodeVectors = Kokkos::View<double* [3]>;

  // Coupled at the nodes alone (shell_midsurface false), or with the shells' mid-surface
  // points: the outer surfaces and cavity walls of the shell cells of `cells`, each shell
  // node's depth δ half its shell's thickness (CaseCells::membrane_depth).
  CellFluidTransfer(const FluidMesh& mesh, double support_factor, const CaseCells& cells, const CaseConfig& config,
                    bool shell_midsurface);

  // The supports and shape functions at the nodes' `positions` [μm] (and at their
  // mid-surface points). Throws PointsOutsideFluidError as RkpmCoupler::update.
  void update(const NodeVectors& positions);
  // values(I, c) = v_I from the fluid's nodal(stride · J + c).
  void interpolate(const Kokkos::View<const double*>& nodal, int stride, const NodeVectors& values) const;
  // nodal(stride · J + c) += (S F)_J: the transpose of interpolate.
  void spread(const NodeVectors& forces, const Kokkos::View<double*>& nodal, int stride) const;

  bool at_midsurface() const { return midsurface_ != nullptr; }
  // Nodes (and mid-surface points) whose RKPM weights needed the linear correction.
  int corrected_points() const;
  // Forces the RKPM correction everywhere (as RkpmCoupler::always_correct).
  void always_correct(bool yes);
  // n̂_I and p_I of the last update (empty without the mid-surface points).
  NodeVectors shell_normals() const { return midsurface_ ? midsurface_->normals : NodeVectors(); }
  NodeVectors midsurface_points() const { return midsurface_ ? midsurface_->points : NodeVectors(); }

 private:
  using Scatter = Kokkos::Experimental::ScatterView<double* [3], typename NodeVectors::array_layout,
                                                    typename Kokkos::DefaultExecutionSpace::device_type>;
  RkpmCoupler at_nodes_;
  struct Midsurface {
    RkpmCoupler rkpm;                   // at the mid-surface points
    Kokkos::View<int* [3]> triangles;   // both surfaces of every shell, oriented out of the solid
    Kokkos::View<double*> depth;        // δ per node [μm]
    NodeVectors normals, points;        // n̂, p
    NodeVectors values, tangential, normal;  // interpolation's and spreading's scratch
    Scatter normal_scatter;
  };
  std::unique_ptr<Midsurface> midsurface_;
};

}  // namespace rouleau
