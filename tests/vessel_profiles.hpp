#pragma once
// Vessel profiles shared by the vessel tests.
#include <Kokkos_Core.hpp>
#include <cmath>
#include <random>

#include "geometry/vessel_profile.hpp"

namespace rouleau::testing {

// A straight tube.
inline VesselProfile tube(double radius, double length) {
  VesselProfile p;
  p.radius = p.throat_radius = radius;
  p.inlet_length = length;
  return p;
}

// A small contraction, 3 → 1.5 μm with cosine transitions, 19 μm long: meshes fast, and
// every part of a profile is in it.
inline VesselProfile small_contraction() {
  VesselProfile p;
  p.radius = 3.0;
  p.throat_radius = 1.5;
  p.inlet_length = 4.0;
  p.contraction_length = 4.0;
  p.throat_length = 3.0;
  p.diffuser_length = 4.0;
  p.outlet_length = 4.0;
  return p;
}

// `count` random points (x, y, z) at radial distance d ∈ [nearest, farthest) from the wall,
// x ∈ [margin, L − margin], at any angle.
inline Kokkos::View<double* [3]> points_near_wall(const VesselProfile& profile, int count, double nearest,
                                                  double farthest, double margin, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> along(margin, vessel_length(profile) - margin),
      angle(0.0, 6.283185307179586), gap(nearest, farthest);
  Kokkos::View<double* [3]> points("points_near_wall", count);
  auto h = Kokkos::create_mirror_view(points);
  for (int p = 0; p < count; ++p) {
    const double x = along(rng), phi = angle(rng), r = vessel_radius(profile, x) - gap(rng);
    h(p, 0) = x;
    h(p, 1) = r * std::cos(phi);
    h(p, 2) = r * std::sin(phi);
  }
  Kokkos::deep_copy(points, h);
  return points;
}

}  // namespace rouleau::testing
