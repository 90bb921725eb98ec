#pragma once
// The fluid setting of the solver's validation tests: unit scales (L = 1 μm, U = 1 μm/s,
// μ = 1 Pa·s, so P = 1 Pa: dimensional = scaled) and tight solver tolerances.
#include "config/case_config.hpp"
#include "fluid/boundary_conditions.hpp"

namespace rouleau::testing {

inline FluidScales unit_scales(double reynolds) {
  FluidScales s;
  s.length = 1.0;
  s.velocity = 1.0;
  s.pressure = 1.0;
  s.reynolds = reynolds;
  return s;
}

// μ = 1 Pa·s and ρ = Re (so that ρUL/μ = Re).
inline FluidConfig unit_fluid(double reynolds) {
  FluidConfig f;
  f.viscosity = 1.0;
  f.density = reynolds;
  return f;
}

inline SolverConfig tight_solver() {
  SolverConfig s;
  s.newton_rtol = 1e-10;
  s.newton_atol = 1e-12;
  s.gmres_rtol = 1e-10;
  s.gmres_restart = 100;
  s.gmres_max_iterations = 20000;
  return s;
}

}  // namespace rouleau::testing
