#pragma once
// Scales, Reynolds number and the Stokes decision derived from a case.
// Host-only: includes no Kokkos header.
#include "config/case_config.hpp"

namespace rouleau {

// Derives the solver's scales and the Stokes decision from a validated case:
//  L = scales.length, or the smallest extent among non-periodic directions (the smallest
//      extent when all are periodic);
//  U = scales.velocity, or the largest of |wall velocity|, inflow mean speeds, the Poiseuille
//      estimates |Δp| L²/(8 μ ℓ) between opposite traction sides ℓ apart and |f| L²/(8 μ)
//      from the body force; 1 μm/s when all are zero;
//  pressure scale μU/L, Re = ρUL/μ; Stokes when solver.stokes = "on", or "auto" and Re is
//  below solver.stokes_reynolds_threshold. stokes_reason says which, in one sentence.
DerivedQuantities derive_quantities(const CaseConfig& config);

}  // namespace rouleau
