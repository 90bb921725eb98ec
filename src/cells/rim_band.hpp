#pragma once
// Where on the cells' surfaces the interaction force acts (Liu et al. 2004, Fig. 7: "the
// interaction forces act mainly at the rims"). A red cell's rims are the crests of its
// biconcave torus, where it is thickest and where a neighbour's face comes closest. A
// cell's rim band is the part of its outer surface at least `rim_height_fraction` of the
// largest height above the cell's mid-plane, in the reference configuration: with 0.75,
// the Evans–Fung cell's band runs from r/R ≈ 0.44 to 0.89 on both faces (0.48 of the
// outer surface's area), leaving out the dimple and the equator. The mid-plane passes through
// the reference surface's area-weighted centroid, normal to the direction of its smallest
// second moment: a disc's symmetry axis. Host-side measure for the diagnostics.
#include <Kokkos_Core.hpp>
#include <vector>

#include "cells/cell_population.hpp"

namespace rouleau {

class RimBand {
 public:
  static constexpr double default_rim_height_fraction = 0.75;
  explicit RimBand(const CellPopulation& population, double rim_height_fraction = default_rim_height_fraction);

  // The band's share of all the cells' outer-surface area (reference), in [0, 1].
  double area_share() const { return area_share_; }
  // The band's share of Σ_n |f_n| over the outer-surface nodes of all cells, for nodal
  // forces [pN] (the Morse forces) given node-major on the host, (f_0x, f_0y, f_0z, f_1x,
  // ...); 0 when every force is zero.
  double force_share(const double* forces) const;
  // Per node: 1 in some cell's rim band, 0 elsewhere (and off the outer surface).
  const std::vector<char>& in_band() const { return in_band_; }

 private:
  std::vector<char> in_band_;
  std::vector<char> on_surface_;
  double area_share_ = 0.0;
};

}  // namespace rouleau
