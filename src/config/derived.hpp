#pragma once
// Scales, Reynolds number and the Stokes decision derived from a case.
// Host-only: includes no Kokkos header.
#include <array>
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

// The strain per step γ̇ Δt up to which the coupling was measured accurate: a stiff
// spheroid's flip from 45° to 135° (cases/spheroid_shear, c/a = 1/3, h_f = 1 μm, the
// semi-implicit coupling) took 0.7 %, 5.4 %, 28.5 % and 96 % longer at γ̇ Δt = 0.025,
// 0.05, 0.1 and 0.2 than at 0.0125; at γ̇ Δt = 0.025 it changed by less than 3 % from 8
// to 133 times the explicit stable step (docs/validation.md, "Rotation of thin bodies").
constexpr double accurate_strain_per_step = 0.05;

// Why a structured box periodic along the axes `periodic`, with `elements` per axis, does
// not allow the fast diagonalization (fluid/fast_diagonalization.hpp); empty when it does:
// exactly two periodic axes, and at least 6 elements along one of them (the probes sit
// half a box away from the pinned dof node 0, beyond a row's reach of 2 planes).
constexpr int fast_diagonalization_min_periodic_elements = 6;
std::string fast_diagonalization_box_obstacle(const std::array<bool, 3>& periodic, const std::array<int, 3>& elements);

// The fluid domain in one line: "8 x 8 x 8 hexahedra (512 elements), 20 x 20 x 20 μm" or
// "vessel of tetrahedra (Gmsh), radius 5 μm, throat 2 μm, length 60 μm, elements 1 μm
// (0.5 μm at the wall)".
std::string describe_fluid_domain(const CaseConfig& config);

}  // namespace rouleau
