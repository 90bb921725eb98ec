#pragma once
// Made-up diagnostics of two cells at a throat from x = 30 to 40 um (the scene checks'
// tests): five rows 1 s apart, x-extent 8 um; cell 0 passes at 3 s, cell 1 reaches the
// entrance (its front at 29.5 um) and stalls there (5 um/s in the first quarter, 0.2 um/s
// in the last); the driving pressure over Hagen–Poiseuille's rises from 1.04 to 3.
#include "analysis/scene_checks.hpp"

namespace rouleau::testing {

inline DiagnosticsRows throat_passage_rows() {
  DiagnosticsRows rows;
  const double x0[5] = {10, 20, 35, 45, 55}, x1[5] = {10, 15, 25, 25.3, 25.5};
  const double pressure_ratio[5] = {1.04, 1.5, 6.0, 3.5, 3.0};
  for (int r = 0; r < 5; ++r)
    rows.push_back({{"time_s", double(r)},
                    {"cell0_centroid_x_um", x0[r]},
                    {"cell1_centroid_x_um", x1[r]},
                    {"cell0_extent_x_um", 8.0},
                    {"cell1_extent_x_um", 8.0},
                    {"relative_apparent_viscosity", pressure_ratio[r]}});
  return rows;
}

}  // namespace rouleau::testing
