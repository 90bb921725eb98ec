#include "coupling/wall_repulsion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "util/profiling_region.hpp"

namespace rouleau {

WallRepulsion::WallRepulsion(const VesselProfile& profile, double pressure, double range, int intervals) {
  if (intervals < 1) throw std::invalid_argument("rouleau::WallRepulsion: the table needs at least 1 interval");
  if (!(range > 0.0)) throw std::invalid_argument("rouleau::WallRepulsion: the range must be > 0");
  const double length = vessel_length(profile), step = length / intervals;
  const double part_lengths[VesselWallRepulsion::max_parts] = {profile.inlet_length, profile.contraction_length,
                                                               profile.throat_length, profile.diffuser_length,
                                                               profile.outlet_length};
  std::vector<double> radius, slope;
  double start = 0.0;
  for (double part_length : part_lengths) {
    if (!(part_length > 0.0)) continue;
    const int p = wall_.parts++;
    const int n = std::max(1, static_cast<int>(std::ceil(part_length / step)));
    wall_.part_start[p] = start;
    wall_.part_spacing[p] = part_length / n;
    wall_.part_first[p] = static_cast<int>(radius.size());
    wall_.part_intervals[p] = n;
    // Knots at the part's own ends, with R and R' of the part itself: at its end knot the
    // slope is taken just inside it (vessel_radius_slope() there gives the next part's,
    // which differs at the corners of a cone).
    for (int k = 0; k <= n; ++k) {
      const double x = start + part_length * k / n;
      radius.push_back(vessel_radius(profile, x));
      slope.push_back(vessel_radius_slope(profile, k < n ? x : x - 1e-9 * part_length));
    }
    start += part_length;
  }
  radius_table_ = Kokkos::View<double*>("rouleau::WallRepulsion::radius_table", radius.size());
  slope_table_ = Kokkos::View<double*>("rouleau::WallRepulsion::slope_table", slope.size());
  auto radius_host = Kokkos::create_mirror_view(radius_table_);
  auto slope_host = Kokkos::create_mirror_view(slope_table_);
  for (std::size_t k = 0; k < radius.size(); ++k) {
    radius_host(k) = radius[k];
    slope_host(k) = slope[k];
  }
  Kokkos::deep_copy(radius_table_, radius_host);
  Kokkos::deep_copy(slope_table_, slope_host);
  wall_.radius_table = radius_table_;
  wall_.slope_table = slope_table_;
  wall_.pressure = pressure;
  wall_.range = range;
}

void WallRepulsion::compute_forces(const ConstNodeVectors& positions, const Kokkos::View<const double*>& area_weights,
                                   const NodeVectors& force) const {
  ProfilingRegion region("rouleau::WallRepulsion::compute_forces");
  WallRepulsionFunctor<NodeVectors, Kokkos::View<const double*>> functor{wall_, positions, area_weights, force};
  Kokkos::parallel_for("rouleau::WallRepulsion::forces",
                       Kokkos::RangePolicy<Kokkos::DefaultExecutionSpace, ForcesOnly>(0, positions.extent(0)), functor);
}

double WallRepulsion::compute_forces_and_energy(const ConstNodeVectors& positions,
                                                const Kokkos::View<const double*>& area_weights,
                                                const NodeVectors& force) const {
  ProfilingRegion region("rouleau::WallRepulsion::compute_forces_and_energy");
  WallRepulsionFunctor<NodeVectors, Kokkos::View<const double*>> functor{wall_, positions, area_weights, force};
  double energy = 0.0;
  Kokkos::parallel_reduce("rouleau::WallRepulsion::forces_and_energy",
                          Kokkos::RangePolicy<Kokkos::DefaultExecutionSpace, ForcesAndEnergy>(0, positions.extent(0)),
                          functor, energy);
  return energy;
}

}  // namespace rouleau
