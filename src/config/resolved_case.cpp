#include "config/resolved_case.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <toml++/toml.h>

#include "config/case_file_names.hpp"
#include "config/cell_kinds.hpp"
#include "config/load_case.hpp"
#include "util/number_text.hpp"
#include "config/toml_table_reader.hpp"

namespace rouleau {
namespace {

std::string toml_text(double value) { return toml_float(value); }
std::string toml_text(int value) { return std::to_string(value); }
std::string toml_text(bool value) { return value ? "true" : "false"; }
std::string toml_text(const std::string& value) {
  std::ostringstream quoted;
  quoted << toml::value<std::string>(value);  // toml++ quotes and escapes
  return quoted.str();
}
std::string toml_text(const char* value) { return toml_text(std::string(value)); }
template <class Number>
std::string toml_text(const std::array<Number, 3>& values) {
  return "[" + toml_text(values[0]) + ", " + toml_text(values[1]) + ", " + toml_text(values[2]) + "]";
}

// Writes TOML tables and keys in the order the case file documents them.
class TomlWriter {
 public:
  void table(const std::string& name, const std::string& comment = "") {
    if (out_.tellp() > 0) out_ << "\n";
    if (!comment.empty()) out_ << "# " << comment << "\n";
    out_ << "[" << name << "]\n";
  }
  // An entry of an array of tables: [[name]].
  void array_table_entry(const std::string& name) {
    if (out_.tellp() > 0) out_ << "\n";
    out_ << "[[" << name << "]]\n";
  }
  template <class Value>
  void key(const std::string& name, const Value& value, const std::string& comment = "") {
    out_ << name << " = " << toml_text(value);
    if (!comment.empty()) out_ << "  # " << comment;
    out_ << "\n";
  }
  void comment(const std::string& text) { out_ << "# " << text << "\n"; }
  std::string text() const { return out_.str(); }

 private:
  std::ostringstream out_;
};

// The value in the file's unit whose conversion at load (× file_to_internal) gives back
// exactly `internal` (the plain quotient can be one unit in the last place off).
double in_file_units(double internal, double file_to_internal) {
  const double quotient = internal / file_to_internal;
  double below = quotient, above = quotient;
  for (int step = 0; step < 8; ++step) {
    if (above * file_to_internal == internal) return above;
    if (below * file_to_internal == internal) return below;
    above = std::nextafter(above, HUGE_VAL);
    below = std::nextafter(below, -HUGE_VAL);
  }
  return quotient;
}

// A table or key name as TOML writes it: bare when it can be, else quoted.
std::string toml_key(const std::string& name) { return is_bare_toml_key(name) ? name : toml_text(name); }

// One [cell_kinds.NAME] table: the keys that apply to its shape and body. Of the two ways
// to give each modulus, the one that reloads to the identical values is written, the other
// is a comment: shear_modulus_Pa (G_s = G h beside it for a shell), and poisson_ratio when
// K is the one ν gives, else bulk_modulus_Pa (the exact K, with ν beside it).
void write_cell_kind(TomlWriter& toml_file, const CellKindConfig& kind) {
  toml_file.table("cell_kinds." + toml_key(kind.name));
  toml_file.key("shape", toml_name(kind.shape));
  toml_file.key("body", toml_name(kind.body));
  switch (kind.shape) {
    case CellShape::rbc:
    case CellShape::sphere: toml_file.key("diameter_um", kind.diameter); break;
    case CellShape::spheroid:
      toml_file.key("diameter_um", kind.diameter);
      toml_file.key("axis_ratio", kind.axis_ratio);
      break;
    case CellShape::sickle:
      toml_file.key("length_um", kind.length);
      toml_file.key("width_um", kind.width);
      toml_file.key("thickness_um", kind.thickness);
      toml_file.key("arc_radius_um", kind.arc_radius);
      break;
  }
  const bool shell = kind.body == CellBody::shell;
  if (shell) toml_file.key("shell_thickness_um", kind.shell_thickness);
  toml_file.key("resolution", toml_name(kind.resolution));
  toml_file.key("mesh_size_um", kind.mesh_size, "0 = the resolution's preset");
  toml_file.key("shear_modulus_Pa", kind.shear_modulus,
                shell ? "membrane G_s = G × shell_thickness = " + toml_float(kind.shear_modulus * kind.shell_thickness) + " pN/μm"
                      : std::string());
  if (bulk_modulus_from_poisson(kind.shear_modulus, kind.poisson_ratio) == kind.bulk_modulus)
    toml_file.key("poisson_ratio", kind.poisson_ratio, "K = 2G(1+ν)/(3(1−2ν)) = " + toml_float(kind.bulk_modulus) + " Pa");
  else
    toml_file.key("bulk_modulus_Pa", kind.bulk_modulus, "ν = (3K−2G)/(2(3K+G)) = " + toml_float(kind.poisson_ratio));
  toml_file.key("density_kg_m3", in_file_units(kind.density, density_kg_m3_to_internal));
  toml_file.key("morse_well_depth_factor", kind.morse_well_depth_factor);
  toml_file.key("strain_hardening_ratio", kind.strain_hardening_ratio,
                "C3/G of W += C3 (J1 − 3)³; 0 = off (Mills et al. 2004: 1/30)");
  toml_file.key("area_modulus_pN_um", kind.area_modulus, "k_A of E_A = k_A (A − A0)² / (2 A0); 0 = off");
  toml_file.key("volume_modulus_Pa", kind.volume_modulus, "k_V of E_V = k_V (V − V0)² / (2 V0); 0 = off");
}

void write_morse(TomlWriter& toml_file, const MorseConfig& morse) {
  toml_file.key("well_depth_pN_um3", morse.well_depth);
  toml_file.key("beta_per_um", morse.beta);
  toml_file.key("zero_force_length_um", morse.zero_force_length);
  toml_file.key("cutoff_um", morse.cutoff);
}

}  // namespace

std::string resolved_case_toml(const CaseConfig& config, const DerivedQuantities& derived) {
  TomlWriter toml_file;
  toml_file.comment("Resolved case: every key with the value the run uses (units in the key names).");
  toml_file.comment("Loads again as a case file; the [derived] table at the end is output-only.");
  if (!config.source_file.empty()) {
    std::string source = config.source_file;  // a comment ends at a line break
    std::replace(source.begin(), source.end(), '\n', ' ');
    toml_file.comment("Resolved from " + source);
  }

  toml_file.table("case");
  toml_file.key("name", config.name);
  toml_file.key("description", config.description);

  toml_file.table("fluid");
  toml_file.key("density_kg_m3", in_file_units(config.fluid.density, density_kg_m3_to_internal));
  toml_file.key("viscosity_Pa_s", config.fluid.viscosity);
  toml_file.key("body_force_Pa_um", config.fluid.body_force);

  // One [boundary.NAME] table.
  const auto boundary_table = [&](const std::string& name, const BoundaryConfig& boundary) {
    toml_file.table("boundary." + name);
    toml_file.key("type", toml_name(boundary.type));
    switch (boundary.type) {
      case BoundaryType::periodic: break;
      case BoundaryType::wall:
        if (!config.vessel.enabled) toml_file.key("velocity_um_s", boundary.velocity);
        break;
      case BoundaryType::inflow:
        toml_file.key("mean_speed_um_s", boundary.mean_speed);
        toml_file.key("profile", toml_name(boundary.profile));
        break;
      case BoundaryType::traction:
        toml_file.key("pressure_Pa", boundary.pressure);
        toml_file.key("parallel_flow", boundary.parallel_flow);
        break;
    }
  };
  if (config.vessel.enabled) {
    const VesselConfig& vessel = config.vessel;
    toml_file.table("vessel");
    toml_file.key("radius_um", vessel.profile.radius);
    toml_file.key("throat_radius_um", vessel.profile.throat_radius);
    toml_file.key("inlet_length_um", vessel.profile.inlet_length);
    toml_file.key("contraction_length_um", vessel.profile.contraction_length);
    toml_file.key("throat_length_um", vessel.profile.throat_length);
    toml_file.key("diffuser_length_um", vessel.profile.diffuser_length);
    toml_file.key("outlet_length_um", vessel.profile.outlet_length);
    toml_file.key("transition", toml_name(vessel.profile.transition));
    toml_file.key("element_size_um", vessel.sizes.element_size);
    toml_file.key("wall_element_size_um", vessel.sizes.wall_element_size);
    toml_file.key("refined_element_scale", vessel.sizes.refined_scale);
    toml_file.key("refined_from_um", vessel.sizes.refined_from);
    toml_file.key("refined_to_um", vessel.sizes.refined_to);
    toml_file.key("allow_squeeze", vessel.allow_squeeze);
    toml_file.key("wall_repulsion_Pa", vessel.wall_repulsion_pressure);
    toml_file.key("wall_repulsion_range_um", vessel.wall_repulsion_range);
    boundary_table("inlet", vessel.inlet);
    boundary_table("outlet", vessel.outlet);
    BoundaryConfig wall;
    boundary_table("wall", wall);
  } else {
    const DomainConfig& domain = config.domain;
    toml_file.table("domain");
    toml_file.key("lower_um", domain.lower);
    toml_file.key("upper_um", domain.upper);
    toml_file.key("elements", domain.elements);
    toml_file.key("wall_grading", domain.wall_grading);
    for (int side = 0; side < 6; ++side) boundary_table(side_names[side], domain.boundary[side]);
  }

  toml_file.table("time");
  toml_file.key("mode", toml_name(config.time.mode));
  toml_file.key("scheme", toml_name(config.time.scheme));
  toml_file.key("dt_s", config.time.dt);
  toml_file.key("end_s", config.time.end);

  const SolverConfig& solver = config.solver;
  toml_file.table("solver");
  toml_file.key("stokes", toml_name(solver.stokes));
  toml_file.key("stokes_reynolds_threshold", solver.stokes_reynolds_threshold);
  toml_file.key("newton_rtol", solver.newton_rtol);
  toml_file.key("newton_atol", solver.newton_atol);
  toml_file.key("newton_step_rtol", solver.newton_step_rtol);
  toml_file.key("newton_max_iterations", solver.newton_max_iterations);
  toml_file.key("gmres_restart", solver.gmres_restart);
  toml_file.key("gmres_rtol", solver.gmres_rtol);
  toml_file.key("gmres_max_iterations", solver.gmres_max_iterations);
  toml_file.key("preconditioner", toml_name(solver.preconditioner));
  toml_file.key("multigrid_smoother", toml_name(solver.multigrid_smoother));
  toml_file.key("multigrid_precision", toml_name(solver.multigrid_precision));
  toml_file.key("starting_guess_solutions", solver.starting_guess_solutions);

  toml_file.table("scales", "0 = derived from the case (see [derived])");
  toml_file.key("length_um", config.scales.length);
  toml_file.key("velocity_um_s", config.scales.velocity);

  toml_file.table("output");
  toml_file.key("fields", config.output.write_fields);
  toml_file.key("fields_every_steps", config.output.fields_every_steps);
  toml_file.key("diagnostics_every_steps", config.output.diagnostics_every_steps);
  toml_file.key("cell_gaps_max_cells", config.output.cell_gaps_max_cells);

  toml_file.table("checkpoint", "besides those at the start, at the end and on a signal; 0 = off");
  toml_file.key("every_steps", config.checkpoint.every_steps);
  toml_file.key("every_minutes", config.checkpoint.every_minutes);
  toml_file.key("keep", config.checkpoint.kept);

  for (const CellKindConfig& kind : config.cell_kinds) write_cell_kind(toml_file, kind);
  for (const CellPlacement& cell : config.cells) {
    toml_file.array_table_entry("cells");
    toml_file.key("kind", cell.kind);
    toml_file.key("center_um", cell.center);
    toml_file.key("orientation_deg", cell.orientation);
  }

  const InteractionConfig& interaction = config.interaction;
  toml_file.table("interaction");
  toml_file.key("enabled", interaction.enabled);
  toml_file.key("quadrature", toml_name(interaction.quadrature));
  toml_file.key("strength_multiplier", interaction.strength);
  toml_file.key("skin_um", interaction.skin);
  write_morse(toml_file, interaction.morse);
  for (const MorsePairConfig& pair : interaction.pairs) {
    toml_file.array_table_entry("interaction.pair");
    toml_file.key("kind_a", pair.kind_a);
    toml_file.key("kind_b", pair.kind_b);
    write_morse(toml_file, pair.morse);
  }

  const CouplingConfig& coupling = config.coupling;
  toml_file.table("coupling");
  toml_file.key("scheme", toml_name(coupling.scheme));
  toml_file.key("support_elements", coupling.support_elements);
  toml_file.key("stable_step_factor", coupling.stable_step_factor);
  toml_file.key("allow_unstable_step", coupling.allow_unstable_step);
  toml_file.key("volume_tolerance", coupling.volume_tolerance);
  toml_file.key("forces_in_stabilization", coupling.forces_in_stabilization,
                "the spread forces' density in SUPG/PSPG's strong residual");
  toml_file.key("subscale_velocity", coupling.subscale_velocity,
                "the cells move with u_h + u', u' = -tau r the PSPG subscale velocity");
  toml_file.key("film_open_gap_um", coupling.film_open_gap, "the sub-grid film model acts below this gap; 0: off");
  toml_file.key("film_model", toml_name(coupling.film_model));
  toml_file.key("gravity_m_s2", std::array<double, 3>{in_file_units(coupling.gravity[0], 1e6),
                                                      in_file_units(coupling.gravity[1], 1e6),
                                                      in_file_units(coupling.gravity[2], 1e6)});
  toml_file.table("scene");
  toml_file.key("skip_unneeded_stages", config.scene.skip_unneeded_stages);

  toml_file.table("derived", "Output only: derived from the keys above; ignored when this file is loaded.");
  toml_file.key("length_scale_um", derived.length_scale);
  toml_file.key("velocity_scale_um_s", derived.velocity_scale);
  toml_file.key("pressure_scale_Pa", derived.pressure_scale);
  toml_file.key("reynolds", derived.reynolds);
  toml_file.key("stokes", derived.stokes);
  toml_file.key("stokes_reason", derived.stokes_reason);
  toml_file.key("preconditioner", toml_name(derived.preconditioner));
  if (derived.stable_dt > 0.0) {
    toml_file.key("stable_dt_s", derived.stable_dt);
    toml_file.key("stable_dt_reason", derived.stable_dt_reason);
  }
  return toml_file.text();
}

}  // namespace rouleau
