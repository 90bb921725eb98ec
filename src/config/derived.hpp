#pragma once
// Scales, Reynolds number and the Stokes decision derived from a case.
// Host-only: includes no Kokkos header.
#include <string>

#include "config/case_config.hpp"

namespace rouleau {

// Derives the solver's scales and the Stokes decision from a validated case:
//  L = scales.length, or the smallest extent among non-periodic directions (the smallest
//      extent when all are periodic); for a vessel the feeders' diameter 2R;
//  U = scales.velocity, or the largest of |wall velocity|, inflow mean speeds, the Poiseuille
//      estimates |Δp| L²/(8 μ ℓ) between opposite traction sides ℓ apart and |f| L²/(8 μ)
//      from the body force; 1 μm/s when all are zero; for a vessel the inflow's mean speed
//      or Hagen–Poiseuille's R² |Δp| / (8 μ ℓ) between pressure inlet and outlet;
//  pressure scale μU/L, Re = ρUL/μ; Stokes when solver.stokes = "on", or "auto" and Re is
//  below solver.stokes_reynolds_threshold. stokes_reason says which, in one sentence.
DerivedQuantities derive_quantities(const CaseConfig& config);

// The fluid domain in one line: "8 x 8 x 8 hexahedra (512 elements), 20 x 20 x 20 μm" or
// "vessel of tetrahedra (Gmsh), radius 5 μm, throat 2 μm, length 60 μm, elements 1 μm
// (0.5 μm at the wall)".
std::string describe_fluid_domain(const CaseConfig& config);

}  // namespace rouleau
