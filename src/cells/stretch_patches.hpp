#pragma once
// The optical-tweezers stretch of one cell (Mills et al. 2004; Dao, Lim & Suresh 2003) as
// a static solve (cells/static_equilibrium.hpp): the two contact patches a pull spreads
// its force over, and the diameters measured as Mills et al. measured them.
#include <Kokkos_Core.hpp>
#include <array>

#include "cells/cell_population.hpp"

namespace rouleau {

// Diameters of a stretched cell, measured like Mills et al. on the video images: the
// axial one along the pull, the transverse one across it in the plane of the disc.
struct StretchDiameters {
  double axial = 0.0;       // largest extent along the pull direction [μm]
  double transverse = 0.0;  // largest extent along the in-plane perpendicular [μm]
  std::array<double, 3> pull_direction{1.0, 0.0, 0.0};
};

// The two contact patches of a cell held at opposite ends (the silica beads of the
// experiment, contact diameter d_c = 2 μm): the outer-surface nodes within d_c/2 of the
// two points where the line through the cell's centroid along `direction` leaves the
// cell's nodes (the extreme node projections). The weights are the reference area weights
// normalised per patch (+ at the end along `direction`, − at the other), so a pull spreads
// the force as a uniform traction F/A_patch over each patch.
template <class ExecSpace>
class BasicStretchPatches {
 public:
  BasicStretchPatches(const BasicCellPopulation<ExecSpace>& cells, int cell, std::array<double, 3> direction,
                      std::array<double, 3> in_plane_transverse, double contact_diameter = 2.0);

  const Kokkos::View<double*>& signed_weights() const { return signed_weights_; }
  int node_count(int side) const { return side > 0 ? positive_nodes_ : negative_nodes_; }
  double patch_area(int side) const { return side > 0 ? positive_area_ : negative_area_; }
  int cell_surface_nodes() const { return surface_nodes_; }

  // Axial diameter along the current pull direction p/|p| (p = Σ w_a x_a), transverse
  // diameter along the in-plane transverse direction made perpendicular to it, both over
  // the cell's nodes at the current positions.
  StretchDiameters diameters(const BasicCellPopulation<ExecSpace>& cells) const;

 private:
  int cell_ = 0;
  std::array<double, 3> transverse_{0.0, 1.0, 0.0};
  Kokkos::View<double*> signed_weights_;
  int positive_nodes_ = 0, negative_nodes_ = 0, surface_nodes_ = 0;
  double positive_area_ = 0.0, negative_area_ = 0.0;
};

using StretchPatches = BasicStretchPatches<Kokkos::DefaultExecutionSpace>;

extern template class BasicStretchPatches<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
