#pragma once
// Vessel profiles shared by the vessel tests.
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

}  // namespace rouleau::testing
