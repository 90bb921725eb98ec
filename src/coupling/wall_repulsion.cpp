#include "coupling/wall_repulsion.hpp"

#include <stdexcept>

#include "run/profiling_region.hpp"

namespace rouleau {

WallRepulsion::WallRepulsion(const VesselProfile& profile, double pressure, double range, int samples) {
  if (samples < 2) throw std::invalid_argument("rouleau::WallRepulsion: the table needs at least 2 samples");
  if (!(range > 0.0)) throw std::invalid_argument("rouleau::WallRepulsion: the range must be > 0");
  const double length = vessel_length(profile);
  radius_table_ = Kokkos::View<double*>("rouleau::WallRepulsion::radius_table", samples);
  slope_table_ = Kokkos::View<double*>("rouleau::WallRepulsion::slope_table", samples);
  auto radius = Kokkos::create_mirror_view(radius_table_);
  auto slope = Kokkos::create_mirror_view(slope_table_);
  for (int k = 0; k < samples; ++k) {
    radius(k) = vessel_radius(profile, length * k / (samples - 1));
    slope(k) = vessel_radius_slope(profile, length * k / (samples - 1));
  }
  Kokkos::deep_copy(radius_table_, radius);
  Kokkos::deep_copy(slope_table_, slope);
  wall_.radius_table = radius_table_;
  wall_.slope_table = slope_table_;
  wall_.spacing = length / (samples - 1);
  wall_.pressure = pressure;
  wall_.range = range;
}

double WallRepulsion::compute(const NodeVectors& positions, const Kokkos::View<double*>& area_weights,
                              const NodeVectors& force) const {
  ProfilingRegion region("rouleau::WallRepulsion::compute");
  WallRepulsionFunctor<NodeVectors, Kokkos::View<double*>> functor{wall_, positions, area_weights, force};
  double energy = 0.0;
  Kokkos::parallel_reduce("rouleau::WallRepulsion::forces",
                          Kokkos::RangePolicy<Kokkos::DefaultExecutionSpace>(0, positions.extent(0)), functor, energy);
  return energy;
}

}  // namespace rouleau
