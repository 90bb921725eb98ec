#pragma once
// The vessel wall's repulsion of cell surface nodes (kernels/wall_repulsion.hpp), set up
// from a case: the lumen's radius tabulated once, the forces and energy on demand.
#include <Kokkos_Core.hpp>

#include "geometry/vessel_profile.hpp"
#include "kernels/wall_repulsion.hpp"

namespace rouleau {

class WallRepulsion {
 public:
  using NodeVectors = Kokkos::View<double* [3]>;
  using ConstNodeVectors = Kokkos::View<const double* [3]>;

  // R(x) and R'(x) tabulated at steps of about L/intervals, the parts' junctions knots;
  // p_w [Pa], d0 [μm].
  WallRepulsion(const VesselProfile& profile, double pressure, double range, int intervals = 2048);

  // force(a) = f_a of every node from its position and reference surface area weight (the
  // coupled step's call: no reduction, no fence).
  void compute_forces(const ConstNodeVectors& positions, const Kokkos::View<const double*>& area_weights,
                      const NodeVectors& force) const;
  // The same, returning Σ E_a [pN·μm].
  double compute_forces_and_energy(const ConstNodeVectors& positions, const Kokkos::View<const double*>& area_weights,
                                   const NodeVectors& force) const;

  const VesselWallRepulsion& kernel() const { return wall_; }

 private:
  Kokkos::View<double*> radius_table_, slope_table_;
  VesselWallRepulsion wall_;
};

}  // namespace rouleau
