#pragma once
// The built-in cell kinds ("normal", "sickle", "capsule"), the paper's membrane constants
// they come from, and the elastic-moduli relations the case loader uses.
// Units: μm, pN, s (moduli in Pa = pN/μm², membrane moduli in pN/μm, density in pN·s²/μm⁴).
// Unit conversions used below:
//   1 dyn/cm = 1e-5 N / 1e-2 m = 1e-3 N/m, and 1 pN/μm = 1e-12 N / 1e-6 m = 1e-6 N/m,
//   so 1 dyn/cm = 1000 pN/μm;   1 dyn·cm = 1e-5 N · 1e-2 m = 1e-7 J = 1e11 pN·μm.
// Host-only: includes no Kokkos header.
#include <string>
#include <vector>

#include "config/case_config.hpp"

namespace rouleau {

// Membrane shear modulus of the RBC membrane, G_s = 4.2e-3 dyn/cm (the paper) = 4.2 pN/μm.
inline constexpr double paper_membrane_shear_modulus = 4.2;  // [pN/μm]
// Membrane bending modulus, κ = 1.8e-12 dyn·cm (the paper) = 0.18 pN·μm.
inline constexpr double paper_bending_modulus = 0.18;  // [pN·μm]
// The paper's area dilation modulus, 500 dyn/cm = 5e5 pN/μm. Deliberately NOT used for the
// bulk modulus (docs/method.md, design decisions): a thin neo-Hookean shell cannot represent it
// and it would cut the explicit time step by ~1e5. K comes from a Poisson ratio instead;
// a kind's area_modulus_pN_um (a global area constraint, off by default) holds the area
// where a scene needs it (the Mills stretch).
inline constexpr double paper_area_dilation_modulus = 5e5;  // [pN/μm] (documentation only)
// Shell thickness h from κ = G_s h²/3: h = sqrt(3κ/G_s) = sqrt(3 · 0.18 / 4.2) = 0.3586 μm,
// rounded to 0.36 μm.
inline constexpr double rbc_shell_thickness = 0.36;  // [μm]
// Poisson ratio that gives the bulk modulus from G (in 0.45–0.49).
inline constexpr double rbc_poisson_ratio = 0.45;
// RBC density, 1100 kg/m³, in pN·s²/μm⁴ (1000 kg/m³ = 1e-9).
inline constexpr double rbc_density = 1.1e-9;  // [pN·s²/μm⁴]
// Normal RBC diameter D (Evans–Fung): 7.82 μm, V = 94.1 μm³, A = 134.1 μm².
inline constexpr double rbc_diameter = 7.82;  // [μm]
// Thickness of the Evans–Fung disc on its axis per unit diameter: 2 R y(0) / D = a0 / 2
// with a0 = 0.207 (0.81 μm for D = 7.82 μm), its thinnest place away from the rim.
inline constexpr double rbc_centre_thickness_per_diameter = 0.207 / 2.0;
// Sickle cells are "stickier": their Morse well depth is 5 times the normal cells'
// (docs/method.md, "The cells"); between a sickle and a normal cell √5 times.
inline constexpr double sickle_morse_well_depth_factor = 5.0;
// Diameter of the sphere with the normal RBC's volume, (6 · 94.1 / π)^(1/3) = 5.64 μm.
inline constexpr double capsule_diameter = 5.64;  // [μm]
// A sickle cell's shear modulus relative to a normal cell's (docs/method.md, "The cells").
inline constexpr double sickle_stiffness_factor = 10.0;

// The built-in kinds, in this order: "normal" (hollow Evans–Fung RBC), "sickle" (hollow
// crescent, G ×10), "capsule" (hollow sphere with the RBC's volume). Every value is
// set and consistent (K from ν).
std::vector<CellKindConfig> builtin_cell_kinds();

// The kind called `name` in the case (config.cell_kinds), or nullptr.
const CellKindConfig* find_cell_kind(const CaseConfig& config, const std::string& name);

// The Morse law between kinds a and b: an [[interaction.pair]] entry's law when there is
// one, else [interaction]'s with De √(f_a f_b) (the kinds' morse_well_depth_factor); its
// De times [interaction].strength_multiplier either way.
MorseConfig morse_law_between(const CaseConfig& config, const CellKindConfig& a, const CellKindConfig& b);

// Bulk modulus of an isotropic solid from its shear modulus and Poisson ratio:
// K = 2G(1+ν) / (3(1−2ν)), for −1 < ν < 1/2. [same unit as G]
double bulk_modulus_from_poisson(double shear_modulus, double poisson_ratio);
// The inverse: ν = (3K − 2G) / (2(3K + G)), which lies in (−1, 1/2) for G, K > 0.
double poisson_from_bulk_modulus(double shear_modulus, double bulk_modulus);

}  // namespace rouleau
