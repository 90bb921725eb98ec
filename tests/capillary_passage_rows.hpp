#pragma once
// Made-up diagnostics of a capsule through a capillary from x = 20 to 40 um (the scene
// checks' and paper rows' tests): free length 6 um; wholly inside (rear past 20, front
// before 40) at x = 26, 30 and 34 as a 9 um slug with the pressure at 3.6-4.0 Pa; its rear
// 2 um out of the capillary at x = 45.5, 3.3 um wide against the front's 3.0; out at 50 um
// with the pressure back at 1.8 Pa from 1.6 at the start.
#include <map>
#include <string>

#include "analysis/scene_checks.hpp"

namespace rouleau::testing {

// One row: the capsule's centroid x, x-extent and radii, and the driving pressure.
inline std::map<std::string, double> capsule_row(double x, double length, double pressure, double rear_radius = 3.0,
                                                 double front_radius = 3.0) {
  return {{"cell0_centroid_x_um", x},
          {"cell0_extent_x_um", length},
          {"driving_pressure_Pa", pressure},
          {"cell0_radius_rear_um", rear_radius},
          {"cell0_radius_front_um", front_radius}};
}

inline DiagnosticsRows capillary_passage_rows() {
  return {capsule_row(7, 6.0, 1.6),  capsule_row(18, 6.4, 2.5), capsule_row(26, 9.0, 3.8),
          capsule_row(30, 9.0, 4.0), capsule_row(34, 9.0, 3.6), capsule_row(39, 8.0, 3.0),
          capsule_row(45.5, 7.0, 2.2, 3.3, 3.0), capsule_row(50, 6.5, 1.8)};
}

}  // namespace rouleau::testing
