#include "config/derived.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "config/cell_kinds.hpp"
#include "geometry/grading.hpp"
#include "geometry/vessel_mesh.hpp"
#include "util/constants.hpp"

namespace rouleau {
namespace {

bool is_periodic_direction(const DomainConfig& domain, int axis) {
  return domain.boundary[2 * axis].type == BoundaryType::periodic;
}

double norm(const std::array<double, 3>& vector) {
  return std::sqrt(vector[0] * vector[0] + vector[1] * vector[1] + vector[2] * vector[2]);
}

// printf-style formatting of one number into a sentence.
std::string formatted(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

double derived_length_scale(const CaseConfig& config) {
  if (config.scales.length > 0) return config.scales.length;
  if (config.vessel.enabled) return 2.0 * config.vessel.profile.radius;  // the feeders' diameter
  const DomainConfig& domain = config.domain;
  double smallest_extent = 0.0, smallest_bounded_extent = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double extent = domain.upper[axis] - domain.lower[axis];
    if (smallest_extent == 0.0 || extent < smallest_extent) smallest_extent = extent;
    if (!is_periodic_direction(domain, axis) && (smallest_bounded_extent == 0.0 || extent < smallest_bounded_extent))
      smallest_bounded_extent = extent;
  }
  return smallest_bounded_extent > 0.0 ? smallest_bounded_extent : smallest_extent;
}

double derived_velocity_scale(const CaseConfig& config, double length_scale) {
  if (config.scales.velocity > 0) return config.scales.velocity;
  const DomainConfig& domain = config.domain;
  const double viscosity = config.fluid.viscosity;
  if (config.vessel.enabled) {
    const VesselConfig& vessel = config.vessel;
    if (vessel.inlet.type == BoundaryType::inflow) return vessel.inlet.mean_speed;
    // Pressure-driven: Hagen–Poiseuille's mean speed R² |Δp| / (8 μ ℓ) in the feeders.
    const double radius = vessel.profile.radius, drop = std::abs(vessel.inlet.pressure - vessel.outlet.pressure);
    const double speed = radius * radius * drop / (8.0 * viscosity * vessel_length(vessel.profile));
    return speed > 0.0 ? speed : 1.0;
  }
  double speed = 0.0;
  for (const BoundaryConfig& side : domain.boundary) {
    if (side.type == BoundaryType::wall) speed = std::max(speed, norm(side.velocity));
    if (side.type == BoundaryType::inflow) speed = std::max(speed, side.mean_speed);
  }
  for (int axis = 0; axis < 3; ++axis) {
    const BoundaryConfig &low = domain.boundary[2 * axis], &high = domain.boundary[2 * axis + 1];
    if (low.type != BoundaryType::traction || high.type != BoundaryType::traction) continue;
    const double distance = domain.upper[axis] - domain.lower[axis];
    // Poiseuille: mean speed ~ |Δp| L² / (8 μ ℓ)
    speed = std::max(speed, std::abs(high.pressure - low.pressure) * length_scale * length_scale / (8.0 * viscosity * distance));
  }
  // body-force-driven channel: mean speed ~ |f| L² / (8 μ)
  speed = std::max(speed, norm(config.fluid.body_force) * length_scale * length_scale / (8.0 * viscosity));
  return speed > 0.0 ? speed : 1.0;
}

// The smallest fluid element edge [μm]: of the box, or the vessel's size field on the
// wall (the throat's, or a refined stretch's).
double smallest_fluid_element(const CaseConfig& config) {
  if (config.vessel.enabled) return smallest_vessel_element_size(config.vessel.profile, config.vessel.sizes);
  const DomainConfig& domain = config.domain;
  double smallest = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double h = smallest_graded_interval(domain.lower[axis], domain.upper[axis], domain.elements[axis],
                                              domain.wall_grading[axis]);
    if (axis == 0 || h < smallest) smallest = h;
  }
  return smallest;
}

// The radius over which a kind's area-constraint mode varies, times ⟨4(H − H̄)²⟩ R/π R:
// the shape factor κ of that mode's stiffness (below), measured on the meshes: 1.6 for the
// Evans–Fung disc (⟨4(H − H̄)²⟩ = 0.33 /μm² at R = 3.91 μm), 0.014 for a sphere (only
// inflation, which the cavity blocks, changes its area); the sickle and the spheroid
// (not measured) are taken as the disc, the larger.
double area_mode_shape_factor(CellShape shape) { return shape == CellShape::sphere ? 0.014 : 1.6; }

// The explicit coupling's stable step (docs/method.md, "The stable step"): a membrane of modulus G_s
// relaxes a wrinkle of the fluid mesh's wavelength h_f through fluid of viscosity μ at the
// rate G_s / (μ h_f), so Δt ≤ C μ h_f / G_eff, with
//   G_eff = (4/3) [G_s (1 + 30 r) + k_A κ h_f / R]:
// G_s = G h for a shell; a filled body is taken as a layer one fluid element thick (the
// fluid resolves nothing thinner): G_s = G h_f. Strain hardening C3 = r G stiffens the
// tangent modulus to G [1 + 30 r (J1 − 3)²], bounded here by (J1 − 3) ≤ 1. The global area
// constraint k_A adds a cell-sized normal mode (the cavity blocks its uniform part) of
// stiffness k_A ⟨4(H − H̄)²⟩ per area and mobility R/(4μ), i.e. a grid-scale modulus of
// k_A κ h_f / R (κ: area_mode_shape_factor). The global volume constraint k_V is left
// out, and the reason says so: its uniform-inflation mode is held back by the enclosed
// fluid as far as the fluid mesh resolves the cell, which no formula here knows (docs/validation.md,
// "What is still weak": stable for the capsule at a/h_f 2.7 and 5.5 with k_V = 50 Pa, divergent
// for a red cell at h_f = 1 μm).
//
// The membrane's G_eff carries a factor 4/3 that the stability map measured
// (bench/stability.py, bench/stability.md): the reduced one-cell shear box at 3 1/s ran 300
// explicit steps within 0.11 % of its volume at 0.75 μ h_f / G_s and drifted 8 % (then
// inverted an element) at 0.9; at 1.0 every membrane-bound scene drifted 4–5 % in 30
// steps. The Morse-bound scenes held at the full estimate (the reduced aggregation at
// 0.96 of it), so the factor is the membrane's alone.
constexpr double membrane_stability_margin = 4.0 / 3.0;

void derive_stable_step(const CaseConfig& config, DerivedQuantities& derived) {
  if (config.cells.empty() || config.time.mode == TimeMode::steady) return;
  const double h_f = smallest_fluid_element(config);
  double stiffest = 0.0;
  std::string stiffest_source;  // what sets G_eff, for the reason
  bool volume_constraint = false;
  for (const CellPlacement& cell : config.cells) {
    const CellKindConfig& kind = *find_cell_kind(config, cell.kind);
    volume_constraint = volume_constraint || kind.volume_modulus > 0.0;
    const double layer = kind.body == CellBody::shell ? kind.shell_thickness : h_f;
    const double radius = 0.5 * (kind.shape == CellShape::sickle ? kind.width : kind.diameter);
    const double effective_modulus =
        membrane_stability_margin * (kind.shear_modulus * layer * (1.0 + 30.0 * kind.strain_hardening_ratio) +
                                     kind.area_modulus * area_mode_shape_factor(kind.shape) * h_f / radius);
    if (effective_modulus > stiffest) {
      stiffest = effective_modulus;
      stiffest_source = "kind " + kind.name + ", the stiffest membrane, with the measured margin 4/3";
    }
  }
  // A vessel wall's repulsion: stiffness ∂f/∂d = 2 p_w A / d0 at contact, over the area
  // h_f² that one fluid element gathers: G_wall = 2 p_w h_f² / d0.
  if (config.vessel.enabled && config.vessel.wall_repulsion_pressure > 0.0) {
    const double wall = 2.0 * config.vessel.wall_repulsion_pressure * h_f * h_f / config.vessel.wall_repulsion_range;
    if (wall > stiffest) {
      stiffest = wall;
      stiffest_source = "the vessel wall's repulsion 2 p_w h_f^2 / d0";
    }
  }
  // The Morse law between two cells' faces at their balance gap h* = r0 − ln2/β (where
  // φ(h*) = 0): the normal pressure between flat faces at gap h is p(h) = 2π h φ(h), so
  // their stiffness there is |dp/dh| = 2π h* |φ'(h*)| = 8π β De h* [Pa/μm]. A patch of
  // the fluid element's size h_f relaxes through the fluid at the rate k h_f / μ, i.e. a
  // grid-scale modulus G_Morse = 8π β De h* h_f², for the strongest law between kinds
  // the case places (two cells or more).
  if (config.interaction.enabled && config.cells.size() >= 2) {
    std::set<std::string> placed_kinds;
    for (const CellPlacement& cell : config.cells) placed_kinds.insert(cell.kind);
    for (const std::string& kind_a : placed_kinds)
      for (const std::string& kind_b : placed_kinds) {
        const MorseConfig law =
            morse_law_between(config, *find_cell_kind(config, kind_a), *find_cell_kind(config, kind_b));
        const double balance_gap = law.zero_force_length - std::log(2.0) / law.beta;
        const double morse = 8.0 * pi * law.beta * law.well_depth * std::max(balance_gap, 0.0) * h_f * h_f;
        if (morse > stiffest) {
          stiffest = morse;
          stiffest_source = "the Morse law between kinds " + kind_a + " and " + kind_b +
                            " at its balance gap, 8 pi beta De h* h_f^2";
        }
      }
  }
  const double C = config.coupling.stable_step_factor;
  derived.stable_dt = C * config.fluid.viscosity * h_f / stiffest;
  derived.stable_dt_reason = "C mu h_f / G_eff = " + formatted("%g", C) + " x " +
                             formatted("%g", config.fluid.viscosity) + " Pa s x " + formatted("%g", h_f) +
                             " um / " + formatted("%g", stiffest) + " pN/um (" + stiffest_source +
                             "; smallest fluid element h_f)" +
                             (volume_constraint ? "; it leaves out the volume constraint (volume_modulus_Pa)" : "");
}

// The flow's largest shear rate as the case sets it:
//   between moving walls ℓ apart: |Δv_t| / ℓ (simple shear);
//   a plane channel of height ℓ with mean speed V (an inflow side, or the Poiseuille
//   estimates of the velocity scale between traction sides or from a body force): the
//   wall's 6 V / ℓ;
//   a vessel with mean speed V in its feeders of radius R: Poiseuille's wall shear rate at
//   the throat, 4 V_t / R_t with V_t = V (R / R_t)².
// The largest of these; 0 when none applies (a closed box at rest).
void derive_shear_rate(const CaseConfig& config, DerivedQuantities& derived) {
  if (config.vessel.enabled) {
    const VesselProfile& profile = config.vessel.profile;
    const double squeeze = profile.radius / profile.throat_radius;
    derived.shear_rate = 4.0 * derived.velocity_scale * squeeze * squeeze / profile.throat_radius;
    derived.shear_rate_source = "Poiseuille's wall shear rate at the throat, 4 V (R/R_t)^2 / R_t";
    return;
  }
  const DomainConfig& domain = config.domain;
  for (int axis = 0; axis < 3; ++axis) {
    const BoundaryConfig &low = domain.boundary[2 * axis], &high = domain.boundary[2 * axis + 1];
    const double distance = domain.upper[axis] - domain.lower[axis];
    double rate = 0.0;
    std::string source;
    if (low.type == BoundaryType::wall && high.type == BoundaryType::wall) {
      // The walls' relative velocity, less its component along the axis (which would move
      // a wall through itself: refused at load).
      std::array<double, 3> relative{high.velocity[0] - low.velocity[0], high.velocity[1] - low.velocity[1],
                                     high.velocity[2] - low.velocity[2]};
      relative[axis] = 0.0;
      rate = norm(relative) / distance;
      source = std::string("the walls' shear across ") + "xyz"[axis];
    }
    const bool driven = low.type == BoundaryType::inflow || high.type == BoundaryType::inflow ||
                        (low.type == BoundaryType::traction && high.type == BoundaryType::traction);
    if (driven && 6.0 * derived.velocity_scale / derived.length_scale > rate) {
      rate = 6.0 * derived.velocity_scale / derived.length_scale;
      source = "a plane channel's wall shear rate 6 U / L";
    }
    if (rate > derived.shear_rate) derived.shear_rate = rate, derived.shear_rate_source = source;
  }
  if (norm(config.fluid.body_force) > 0.0 && 6.0 * derived.velocity_scale / derived.length_scale > derived.shear_rate) {
    derived.shear_rate = 6.0 * derived.velocity_scale / derived.length_scale;
    derived.shear_rate_source = "a plane channel's wall shear rate 6 U / L";
  }
}

// The strain per step, and the warning when it is beyond accurate_strain_per_step.
void derive_step_accuracy(const CaseConfig& config, DerivedQuantities& derived) {
  if (config.cells.empty() || config.time.mode == TimeMode::steady) return;
  derive_shear_rate(config, derived);
  derived.strain_per_step = derived.shear_rate * config.time.dt;
  if (derived.strain_per_step > accurate_strain_per_step)
    derived.accuracy_warning =
        "the strain per step, shear rate x dt = " + formatted("%.3g", derived.shear_rate) + " 1/s x " +
        formatted("%g", config.time.dt) + " s = " + formatted("%.3g", derived.strain_per_step) +
        ", is beyond the " + formatted("%g", accurate_strain_per_step) +
        " up to which the coupling was measured accurate (stable is not accurate): dt <= " +
        formatted("%.3g", accurate_strain_per_step / derived.shear_rate) + " s keeps a stiff body's turning " +
        "within about 5 % of the small-step answer";
}

}  // namespace

std::string fast_diagonalization_box_obstacle(const std::array<bool, 3>& periodic, const std::array<int, 3>& elements) {
  int periodic_axes = 0, longest_periodic = 0;
  for (int axis = 0; axis < 3; ++axis)
    if (periodic[axis]) {
      ++periodic_axes;
      longest_periodic = std::max(longest_periodic, elements[axis]);
    }
  if (periodic_axes != 2) return "is periodic along " + std::to_string(periodic_axes) + " axes";
  if (longest_periodic < fast_diagonalization_min_periodic_elements)
    return "has fewer than " + std::to_string(fast_diagonalization_min_periodic_elements) +
           " elements along both periodic axes";
  return "";
}

namespace {
// derived.preconditioner: "auto" becomes fast diagonalization where it applies (a box
// periodic along two axes and uniform along them, at least 6 elements along one, in the
// Stokes limit, in a build whose vectors the host threads read; fluid/fast_diagonalization.hpp)
// and the multigrid elsewhere (run/simulation.cpp also takes the multigrid across ranks).
void derive_preconditioner(const CaseConfig& config, DerivedQuantities& derived) {
  std::string& obstacle = derived.fast_diagonalization_obstacle;
  if (config.vessel.enabled) {
    obstacle = "this case's fluid mesh is a vessel's tetrahedra";
  } else {
    std::array<bool, 3> periodic{};
    for (int axis = 0; axis < 3; ++axis) {
      periodic[axis] = config.domain.boundary[2 * axis].type == BoundaryType::periodic;
      if (periodic[axis] && config.domain.wall_grading[axis] != 1.0 && obstacle.empty())
        obstacle = "this box is graded along a periodic axis (domain.wall_grading)";
    }
    const std::string shape = fast_diagonalization_box_obstacle(periodic, config.domain.elements);
    if (!shape.empty()) obstacle = "this box " + shape;
  }
  if (obstacle.empty() && !derived.stokes) obstacle = "this flow is not in the Stokes limit (solver.stokes)";
#if ROULEAU_DEVICE_MEMORY
  // fluid/fast_diagonalization.cpp runs on the host threads, over the fluid's vectors.
  if (obstacle.empty()) obstacle = "this build keeps the fluid's vectors in a GPU's memory";
#endif
  derived.preconditioner = config.solver.preconditioner;
  if (derived.preconditioner == PreconditionerType::automatic)
    derived.preconditioner = obstacle.empty() ? PreconditionerType::fast_diagonalization : PreconditionerType::multigrid;
}
}  // namespace

DerivedQuantities derive_quantities(const CaseConfig& config) {
  DerivedQuantities derived;
  derived.length_scale = derived_length_scale(config);
  derived.velocity_scale = derived_velocity_scale(config, derived.length_scale);
  derived.pressure_scale = config.fluid.viscosity * derived.velocity_scale / derived.length_scale;
  derived.reynolds = config.fluid.density * derived.velocity_scale * derived.length_scale / config.fluid.viscosity;

  const std::string reynolds = "Re = " + formatted("%.2g", derived.reynolds);
  const std::string threshold = formatted("%g", config.solver.stokes_reynolds_threshold);
  switch (config.solver.stokes) {
    case StokesChoice::on:
      derived.stokes = true;
      derived.stokes_reason = "solver.stokes = \"on\" (" + reynolds +
                              "): convective term dropped (changes the answer by O(Re))";
      break;
    case StokesChoice::off:
      derived.stokes = false;
      derived.stokes_reason = "solver.stokes = \"off\" (" + reynolds + "): convective term kept (Navier–Stokes)";
      break;
    case StokesChoice::automatic:
      derived.stokes = derived.reynolds < config.solver.stokes_reynolds_threshold;
      derived.stokes_reason =
          derived.stokes ? reynolds + " < threshold " + threshold +
                               ": convective term dropped (changes the answer by O(Re)); set solver.stokes = \"off\" "
                               "to keep it"
                         : reynolds + " ≥ threshold " + threshold + ": convective term kept (Navier–Stokes)";
      break;
  }
  derive_preconditioner(config, derived);
  derive_stable_step(config, derived);
  derive_step_accuracy(config, derived);
  return derived;
}

std::string describe_fluid_domain(const CaseConfig& config) {
  char text[256];
  if (config.vessel.enabled) {
    const VesselConfig& v = config.vessel;
    const double wall = v.sizes.wall_element_size > 0.0 ? v.sizes.wall_element_size : v.sizes.element_size;
    int written = std::snprintf(text, sizeof(text),
                                "vessel of tetrahedra (Gmsh), radius %g μm, throat %g μm, length %g μm, elements %g μm "
                                "(%g μm at the wall)",
                                v.profile.radius, v.profile.throat_radius, vessel_length(v.profile),
                                v.sizes.element_size, wall);
    if (v.sizes.refined_scale < 1.0 && written > 0 && written < static_cast<int>(sizeof(text)))
      std::snprintf(text + written, sizeof(text) - written, ", × %g from x = %g to %g μm", v.sizes.refined_scale,
                    v.sizes.refined_from, v.sizes.refined_to);
    return text;
  }
  const DomainConfig& d = config.domain;
  const long long count = static_cast<long long>(d.elements[0]) * d.elements[1] * d.elements[2];
  std::snprintf(text, sizeof(text), "%d x %d x %d hexahedra (%lld elements), %g x %g x %g μm", d.elements[0],
                d.elements[1], d.elements[2], count, d.upper[0] - d.lower[0], d.upper[1] - d.lower[1],
                d.upper[2] - d.lower[2]);
  return text;
}

}  // namespace rouleau
