#pragma once
// Shape measures of each cell in the shear plane (x–y), from its outer-surface nodes:
//   inclination  the angle from +x of the major axis of the in-plane gyration tensor
//                G = Σ_n w_n r_n r_nᵀ (r_n = (x_n − x_c, y_n − y_c), w_n the nodes' area
//                weights), in degrees in (−90, 90];
//   L, B         the largest and smallest distance to the centroid of the membrane's
//                mid-surface in the shear plane (docs/validation.md, "The coupling"): among the
//                outer-surface nodes in a slab |z − z_c| < δ about the cell's mid-plane,
//                δ = 0.6 × the mean outer-surface edge, the largest and smallest distance
//                less the membrane's depth below the outer surface (half the thickness of
//                a hollow shell, whose mid-surface is the thin membrane it stands for; the
//                shell thins where it stretches, which this leaves out: for a 0.18 μm
//                shell stretched 20 %, 0.015 μm of a 3 μm radius);
//   D            the Taylor deformation (L − B) / (L + B);
// and, in 3D, the extent of the outer surface along x, y and z (its bounding box: a
// capsule's length and width in a capillary along x), and the radii of its front and
// rear along x: the largest distance √((y − y_c)² + (z − z_c)²) from the line along x
// through the centroid among the outer-surface nodes ahead of the centroid (x > x_c) and
// behind it (a capsule leaving a capillary with a flared rear, the paper's jellyfish, has
// R_rear > R_front).
#include <vector>

#include "cells/cell_population.hpp"

namespace rouleau {

struct ShearPlaneShape {
  double inclination_deg = 0.0;
  double length = 0.0;   // L [μm]
  double breadth = 0.0;  // B [μm]
  double taylor_deformation = 0.0;
  double extent[3] = {0.0, 0.0, 0.0};  // [μm] max − min of the outer-surface nodes' x, y, z
  double radius_front = 0.0;           // R_front [μm]
  double radius_rear = 0.0;            // R_rear [μm]
};

// One entry per cell; `measures` are population.measures() at the same positions;
// membrane_depth per cell [μm] (CaseCells::membrane_depth), empty = 0 for every cell.
std::vector<ShearPlaneShape> shear_plane_shapes(const CellPopulation& population,
                                                const std::vector<CellMeasures>& measures,
                                                const std::vector<double>& membrane_depth = {});

}  // namespace rouleau
