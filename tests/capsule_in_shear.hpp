#pragma once
// A capsule in simple shear for the tests (tests/long_capsule_shear.cpp at full
// resolution, tests/test_coupling.cpp coarse): runs cases/capsule_shear/case.toml with the
// walls set for a capillary number Ca = μ γ̇ a / E_s (E_s = 3 G_s, a the membrane's
// mid-surface radius) and returns the steady Taylor deformation and the volume kept.
#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cells/cell_shape.hpp"
#include "config/cell_kinds.hpp"
#include "config/load_case.hpp"
#include "geometry/cell_mesh.hpp"
#include "run/simulation.hpp"

namespace rouleau::testing {

struct CapsuleResult {
  double capillary_number = 0.0;
  double deformation = 0.0;       // D averaged over the last 20 % of the run
  double deformation_drift = 0.0;  // D at the end less D at 80 % of the run
  double inclination_deg = 0.0;
  double largest_volume_change = 0.0;  // |V/V0 − 1|, largest over the run
  double final_volume_change = 0.0;    // V/V0 − 1 at the end
  double a_over_h = 0.0;
};

// The capsule case with both walls moving at ±U, U = γ̇ H/2 and γ̇ = 3 Ca G_s / (μ a),
// a the membrane's mid-surface radius.
// `overrides` change the case further (resolution, time span).
inline CapsuleResult run_capsule(double capillary_number, std::vector<std::string> overrides = {}) {
  const std::string case_file = std::string(ROULEAU_SOURCE_DIR) + "/cases/capsule_shear/case.toml";
  rouleau::CaseConfig config = rouleau::load_case(case_file, overrides);
  const rouleau::CellKindConfig& capsule = *rouleau::find_cell_kind(config, config.cells.at(0).kind);
  const double radius = 0.5 * (capsule.diameter - capsule.shell_thickness);
  const double membrane_shear_modulus = capsule.shear_modulus * capsule.shell_thickness;
  const double shear_rate = 3.0 * capillary_number * membrane_shear_modulus / (config.fluid.viscosity * radius);
  const double half_height = 0.5 * (config.domain.upper[1] - config.domain.lower[1]);
  const std::string wall = std::to_string(shear_rate * half_height);
  overrides.push_back("boundary.y_max.velocity_um_s=[" + wall + ", 0, 0]");
  overrides.push_back("boundary.y_min.velocity_um_s=[-" + wall + ", 0, 0]");
  config = rouleau::load_case(case_file, overrides);

  rouleau::Simulation simulation(config, rouleau::default_mesh_cache_dir());
  const auto& cells = simulation.cells();
  const double initial_volume = cells.population->measures().at(0).volume;
  const int steps = static_cast<int>(std::llround(config.time.end / config.time.dt));
  CapsuleResult result;
  result.capillary_number = capillary_number;
  result.a_over_h = radius / ((config.domain.upper[0] - config.domain.lower[0]) / config.domain.elements[0]);
  std::vector<double> late;  // D over the last 20 % of the steps
  double deformation_at_80 = 0.0;
  for (int step = 1; step <= steps; ++step) {
    simulation.advance();
    const auto measures = cells.population->measures();
    result.largest_volume_change =
        std::max(result.largest_volume_change, std::fabs(measures.at(0).volume / initial_volume - 1.0));
    if (step >= steps * 4 / 5) {
      const auto shape = rouleau::shear_plane_shapes(*cells.population, measures, cells.membrane_depth).at(0);
      if (late.empty()) deformation_at_80 = shape.taylor_deformation;
      late.push_back(shape.taylor_deformation);
      result.inclination_deg = shape.inclination_deg;
    }
  }
  result.final_volume_change = cells.population->measures().at(0).volume / initial_volume - 1.0;
  for (double d : late) result.deformation += d / late.size();
  result.deformation_drift = late.back() - deformation_at_80;
  std::printf("capsule Ca = %.4f (shear rate %.1f /s, a/h_f = %.2f, gamma t = %.2f): D = %.4f (drift over the last "
              "20 %%: %+.4f), inclination %.1f deg, largest volume change %.2e, at the end %+.3f %%\n",
              capillary_number, shear_rate, result.a_over_h, shear_rate * config.time.end, result.deformation,
              result.deformation_drift, result.inclination_deg, result.largest_volume_change,
              100.0 * result.final_volume_change);
  return result;
}

}  // namespace rouleau::testing
