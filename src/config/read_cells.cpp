// The readers of the cells: [cell_kinds.NAME] (the built-in kinds, changed or added to),
// [[cells]] and the interaction between them, [interaction] and [[interaction.pair]].
#include <algorithm>
#include <cmath>

#include "config/case_section_readers.hpp"
#include "config/cell_kinds.hpp"
#include "util/number_text.hpp"

namespace rouleau {
namespace {

bool contains_name(const std::vector<std::string_view>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The names of the kinds, for a key that names one.
std::vector<std::string_view> names_of_kinds(const std::vector<CellKindConfig>& kinds) {
  std::vector<std::string_view> names;
  for (const CellKindConfig& kind : kinds) names.push_back(kind.name);
  return names;
}

// The keys that apply to a shell body only.
const std::vector<std::string_view> shell_body_keys{"shell_thickness_um", "membrane_shear_modulus_pN_um"};

// The size keys of each shape.
std::vector<std::string_view> size_keys_of(CellShape shape) {
  switch (shape) {
    case CellShape::rbc:
    case CellShape::sphere: return {"diameter_um"};
    case CellShape::spheroid: return {"diameter_um", "axis_ratio"};
    case CellShape::sickle: return {"length_um", "width_um", "thickness_um", "arc_radius_um"};
  }
  return {};
}

// Rejects size keys of another shape and shell keys on a filled body.
void check_keys_apply_to_shape_and_body(const TableReader& reader, const CellKindConfig& kind) {
  const std::vector<std::string_view> own_size_keys = size_keys_of(kind.shape);
  for (const std::string& key : reader.present_keys()) {
    const bool size_key =
        std::any_of(cell_shape_names.begin(), cell_shape_names.end(),
                    [&](const NamedChoice<CellShape>& shape) { return contains_name(size_keys_of(shape.value), key); });
    if (size_key && !contains_name(own_size_keys, key))
      reader.fail(key, "does not belong to shape \"" + std::string(toml_name(kind.shape)) + "\" (its size keys are " +
                           joined(own_size_keys, false) + ")");
    if (kind.body == CellBody::filled && contains_name(shell_body_keys, key))
      reader.fail(key, std::string("applies to body = \"shell\" only, and this kind's body is \"filled\"") +
                           (key == "membrane_shear_modulus_pN_um" ? " (give shear_modulus_Pa)" : ""));
  }
}

// Fails when the file gives both of two keys that set the same quantity.
void check_not_both(const TableReader& reader, std::string_view first, std::string_view second) {
  if (reader.has(first) && reader.has(second))
    reader.fail(second, "give either " + std::string(first) + " or " + std::string(second) + ", not both");
}

// Shear modulus G [Pa] from shear_modulus_Pa or membrane_shear_modulus_pN_um (G = G_s / h),
// bulk modulus K [Pa] from bulk_modulus_Pa or poisson_ratio. K follows G through ν unless
// bulk_modulus_Pa is given; then ν is the one K and G imply.
void read_cell_moduli(const TableReader& reader, CellKindConfig& kind) {
  check_not_both(reader, "shear_modulus_Pa", "membrane_shear_modulus_pN_um");
  check_not_both(reader, "bulk_modulus_Pa", "poisson_ratio");
  assign(kind.shear_modulus, reader.number("shear_modulus_Pa"));
  if (const auto membrane_shear_modulus = reader.number("membrane_shear_modulus_pN_um"))
    kind.shear_modulus = *membrane_shear_modulus / kind.shell_thickness;  // [pN/μm / μm = Pa]
  if (const auto bulk_modulus = reader.number("bulk_modulus_Pa")) {
    kind.bulk_modulus = *bulk_modulus;
    kind.poisson_ratio = poisson_from_bulk_modulus(kind.shear_modulus, kind.bulk_modulus);
  } else {
    assign(kind.poisson_ratio, reader.number("poisson_ratio"));
    kind.bulk_modulus = bulk_modulus_from_poisson(kind.shear_modulus, kind.poisson_ratio);
  }
}

// The smallest half-dimension of a body [μm] (a shell must be thinner) and what it is.
struct HalfDimension {
  double value;
  std::string what;
};
HalfDimension smallest_half_dimension(const CellKindConfig& kind) {
  switch (kind.shape) {
    case CellShape::rbc: {
      const double centre_thickness = rbc_centre_thickness_per_diameter * kind.diameter;
      return {0.5 * centre_thickness, "half the disc's thickness on its axis (" +
                                          format_number(rbc_centre_thickness_per_diameter) +
                                          " × diameter_um = " + format_number(centre_thickness) + " μm)"};
    }
    case CellShape::sphere: return {0.5 * kind.diameter, "the radius (diameter_um / 2)"};
    case CellShape::spheroid:  // filled only: no shell needs this
      return {0.5 * kind.diameter * std::min(1.0, kind.axis_ratio), "the smaller semi-axis"};
    case CellShape::sickle: {
      HalfDimension smallest{0.5 * kind.length, "length_um / 2"};
      if (0.5 * kind.width < smallest.value) smallest = {0.5 * kind.width, "width_um / 2"};
      if (0.5 * kind.thickness < smallest.value) smallest = {0.5 * kind.thickness, "thickness_um / 2"};
      return smallest;
    }
  }
  return {0.0, "?"};
}

// Checks that the sizes of a kind make a body: a sickle's arc wider than its half-width,
// a shell thinner than the body's smallest half-dimension.
void check_cell_body(const TableReader& reader, const CellKindConfig& kind) {
  if (kind.shape == CellShape::sickle && !(kind.arc_radius > 0.5 * kind.width))
    reader.fail("arc_radius_um", "must be > width_um / 2 = " + format_number(0.5 * kind.width) +
                                     " μm (else the crescent's inner edge crosses its centre of curvature), got " +
                                     format_number(kind.arc_radius));
  if (kind.shape == CellShape::spheroid && kind.body == CellBody::shell)
    reader.fail("body", "a spheroid is meshed as a filled body only: give body = \"filled\" (the default is \"shell\")");
  if (kind.body != CellBody::shell) return;
  const HalfDimension limit = smallest_half_dimension(kind);
  if (!(kind.shell_thickness < limit.value))
    reader.fail("shell_thickness_um", "must be < " + format_number(limit.value) + " μm, " + limit.what + ", got " +
                                          format_number(kind.shell_thickness));
}

// One [cell_kinds.NAME] table, applied over `kind` (the built-in kind or the starting values).
void read_cell_kind(const TableReader& reader, CellKindConfig& kind) {
  assign(kind.shape, reader.choice<CellShape>("shape"));
  assign(kind.body, reader.choice<CellBody>("body"));
  check_keys_apply_to_shape_and_body(reader, kind);
  assign(kind.diameter, reader.number("diameter_um"));
  assign(kind.axis_ratio, reader.number("axis_ratio"));
  assign(kind.length, reader.number("length_um"));
  assign(kind.width, reader.number("width_um"));
  assign(kind.thickness, reader.number("thickness_um"));
  assign(kind.arc_radius, reader.number("arc_radius_um"));
  assign(kind.shell_thickness, reader.number("shell_thickness_um"));
  assign(kind.resolution, reader.choice<MeshResolution>("resolution"));
  assign(kind.mesh_size, reader.number("mesh_size_um"));
  read_cell_moduli(reader, kind);
  assign(kind.density, read_density(reader));
  assign(kind.morse_well_depth_factor, reader.number("morse_well_depth_factor"));
  assign(kind.strain_hardening_ratio, reader.number("strain_hardening_ratio"));
  assign(kind.area_modulus, reader.number("area_modulus_pN_um"));
  assign(kind.volume_modulus, reader.number("volume_modulus_Pa"));
  check_cell_body(reader, kind);
}

// The Morse keys of `reader` over `morse`; β must exceed ln 2 / r0 (flat faces then balance
// at a positive gap) and the cut-off r0.
void read_morse(const TableReader& reader, MorseConfig& morse) {
  assign(morse.well_depth, reader.number("well_depth_pN_um3"));
  assign(morse.beta, reader.number("beta_per_um"));
  assign(morse.zero_force_length, reader.number("zero_force_length_um"));
  assign(morse.cutoff, reader.number("cutoff_um"));
  const double least_beta = std::log(2.0) / morse.zero_force_length;
  if (!(morse.beta > least_beta))
    reader.fail(reader.has("beta_per_um") ? "beta_per_um" : "zero_force_length_um",
                "β must be > ln 2 / r0 = " + format_number(least_beta) + " /μm (else flat faces pull into contact); got β = " +
                    format_number(morse.beta) + " /μm, r0 = " + format_number(morse.zero_force_length) + " μm");
  if (!(morse.cutoff > morse.zero_force_length))
    reader.fail("cutoff_um", "must be > zero_force_length_um (" + format_number(morse.zero_force_length) + "), got " +
                                 format_number(morse.cutoff));
}

}  // namespace

// [cell_kinds.NAME]: the built-in kinds, changed by tables of their name, then the kinds
// the file adds (in name order), each starting from the built-in "normal" cell.
void read_cell_kinds(const TableReader& root, std::vector<CellKindConfig>& kinds) {
  kinds = builtin_cell_kinds();
  const CellKindConfig builtin_normal = kinds.front();
  const TableReader section = root.table_of_names("cell_kinds");
  for (const std::string& name : section.present_keys()) {
    if (!is_bare_toml_key(name)) section.fail(name, "a cell kind's name is letters, digits, '_' and '-'");
    const auto builtin = std::find_if(kinds.begin(), kinds.end(), [&](const CellKindConfig& kind) { return kind.name == name; });
    CellKindConfig kind = builtin != kinds.end() ? *builtin : builtin_normal;
    kind.name = name;
    read_cell_kind(section.table(name, "cell_kinds.NAME"), kind);
    if (builtin != kinds.end()) *builtin = kind;
    else kinds.push_back(kind);
  }
}

// [[cells]]: the cells placed in the domain (their placement is checked once the whole
// case is read: cell_placement_check.hpp).
void read_cells(const TableReader& root, CaseConfig& config) {
  const std::vector<std::string_view> kind_names = names_of_kinds(config.cell_kinds);
  for (const TableReader& entry : root.array_of_tables("cells")) {
    CellPlacement cell;
    assign(cell.kind, entry.kind_name("kind", kind_names));
    cell.center = require(entry, "center_um", entry.number3("center_um"));
    assign(cell.orientation, entry.number3("orientation_deg"));
    config.cells.push_back(cell);
  }
}

// [interaction] and its [[interaction.pair]] laws, each pair of kinds at most once.
void read_interaction(const TableReader& root, CaseConfig& config) {
  const TableReader section = root.table("interaction");
  InteractionConfig& interaction = config.interaction;
  assign(interaction.enabled, section.boolean("enabled"));
  assign(interaction.quadrature, section.choice<InteractionQuadrature>("quadrature"));
  assign(interaction.strength, section.number("strength_multiplier"));
  assign(interaction.skin, section.number("skin_um"));
  read_morse(section, interaction.morse);
  const std::vector<std::string_view> kind_names = names_of_kinds(config.cell_kinds);
  for (const TableReader& entry : section.array_of_tables("pair")) {
    MorsePairConfig pair;
    pair.kind_a = require(entry, "kind_a", entry.kind_name("kind_a", kind_names));
    pair.kind_b = require(entry, "kind_b", entry.kind_name("kind_b", kind_names));
    pair.morse = interaction.morse;
    read_morse(entry, pair.morse);
    for (const MorsePairConfig& other : interaction.pairs)
      if ((other.kind_a == pair.kind_a && other.kind_b == pair.kind_b) ||
          (other.kind_a == pair.kind_b && other.kind_b == pair.kind_a))
        entry.fail("kind_b", "the pair " + pair.kind_a + "–" + pair.kind_b + " is given twice");
    interaction.pairs.push_back(pair);
  }
  if (interaction.enabled && config.cells.empty())
    section.fail("enabled", "the interaction acts between cells, and the case has no [[cells]]");
}

}  // namespace rouleau
