#pragma once
// The axisymmetric vessels (docs/vessels.md) as a radius profile r(x) along the axis (x), the
// shape the Gmsh vessel mesher revolves: a straight tube, or a tube with a contraction
// and diffuser (the paper's micro-vessel contraction, Figs. 13–15; a capillary with
// straight feeders, Figs. 16–17, is the same shape with a long narrow throat). Along x:
//
//   inlet feeder   [0, L_in)              r = R
//   contraction    [L_in, L_in + L_c)     r from R to R_t
//   throat         next L_t               r = R_t
//   diffuser       next L_d               r from R_t back to R
//   outlet feeder  next L_out             r = R
//
// Transitions are a cosine, r = R_t + (R − R_t)(1 + cos(π s))/2 with s ∈ [0, 1] across the
// contraction (reversed across the diffuser): smooth (dr/dx continuous, zero at both
// ends), or a straight cone. A tube is R_t = R with L_c = L_t = L_d = 0.
// Host-only: includes no Kokkos header.
#include <array>
#include <optional>
#include <string>

#include "geometry/named_choice.hpp"

namespace rouleau {

enum class VesselTransition { cosine, cone };
// The case-file spelling of each transition (key vessel.transition).
inline constexpr std::array<NamedChoice<VesselTransition>, 2> vessel_transition_names{
    {{VesselTransition::cosine, "cosine"}, {VesselTransition::cone, "cone"}}};

struct VesselProfile {
  double radius = 5.0;              // R, inlet and outlet [μm]
  double throat_radius = 5.0;       // R_t [μm]
  double inlet_length = 20.0;       // L_in [μm]
  double contraction_length = 0.0;  // L_c [μm]
  double throat_length = 0.0;       // L_t [μm]
  double diffuser_length = 0.0;     // L_d [μm]
  double outlet_length = 0.0;       // L_out [μm]
  VesselTransition transition = VesselTransition::cosine;
};

// L = L_in + L_c + L_t + L_d + L_out [μm].
double vessel_length(const VesselProfile& profile);

// r(x) [μm] for 0 ≤ x ≤ L (clamped outside).
double vessel_radius(const VesselProfile& profile, double x);

// dr/dx at x (0 on the straight parts; at the parts' junctions the value of the part x
// starts; both transitions are C¹ there for the cosine).
double vessel_radius_slope(const VesselProfile& profile, double x);

// The lumen's volume π ∫ r(x)² dx [μm³], exactly: the straight parts π R² L, a cosine
// transition π L (3R² + 2R R_t + 3R_t²)/8, a cone π L (R² + R R_t + R_t²)/3.
double vessel_volume(const VesselProfile& profile);

// Hagen–Poiseuille's pressure drop along the vessel for a flow rate Q [μm³/s] of fluid of
// viscosity μ [Pa·s], summed over cross-sections (lubrication): Δp = (8 μ Q / π) ∫ dx / r(x)⁴
// [Pa]. Exact for a tube; in a contraction it leaves out the entrance and exit losses.
double vessel_poiseuille_drop(const VesselProfile& profile, double viscosity, double flow_rate);

// What is wrong with a profile, if anything: the name of the offending quantity (the
// config key's last part: "radius_um", "throat_radius_um", "inlet_length_um", ...) and the
// reason, for one clear line at load. Refused: a radius ≤ 0; a throat wider than the
// inlet; a negative length; a vessel of zero length; feeders of zero length (the inlet
// and outlet conditions need a straight end); a transition without a throat change or a
// throat change without both transitions.
struct VesselProfileProblem {
  std::string key;
  std::string reason;
};
std::optional<VesselProfileProblem> vessel_profile_problem(const VesselProfile& profile);

}  // namespace rouleau
