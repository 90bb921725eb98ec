#include "config/cell_kinds.hpp"

#include <algorithm>
#include <cmath>

namespace rouleau {
namespace {

// A hollow cell with the RBC membrane: shell thickness h = 0.36 μm, 3D shear modulus
// G = G_s / h = 4.2 / 0.36 = 11.67 Pa scaled by `stiffness_factor`, K from ν = 0.45,
// density 1100 kg/m³, the paper's mesh resolution. Shape and size are set by the caller.
CellKindConfig membrane_cell(const std::string& name, CellShape shape, double stiffness_factor) {
  CellKindConfig kind;
  kind.name = name;
  kind.shape = shape;
  kind.body = CellBody::shell;
  kind.shell_thickness = rbc_shell_thickness;
  kind.resolution = MeshResolution::paper;
  kind.mesh_size = 0.0;
  kind.shear_modulus = stiffness_factor * paper_membrane_shear_modulus / rbc_shell_thickness;
  kind.poisson_ratio = rbc_poisson_ratio;
  kind.bulk_modulus = bulk_modulus_from_poisson(kind.shear_modulus, kind.poisson_ratio);
  kind.density = rbc_density;
  return kind;
}

}  // namespace

std::vector<CellKindConfig> builtin_cell_kinds() {
  // Normal RBC: the Evans–Fung biconcave disc of the paper, D = 7.82 μm.
  CellKindConfig normal = membrane_cell("normal", CellShape::rbc, 1.0);
  normal.diameter = rbc_diameter;

  // Sickle cell: an ellipsoid 14 × 4.2 × 3.0 μm bent along an 8 μm arc (a crescent of
  // about the normal cell's volume), ten times stiffer and five times stickier (docs/method.md,
  // "The cells").
  CellKindConfig sickle = membrane_cell("sickle", CellShape::sickle, sickle_stiffness_factor);
  sickle.length = 14.0;
  sickle.width = 4.2;
  sickle.thickness = 3.0;
  sickle.arc_radius = 8.0;
  sickle.morse_well_depth_factor = sickle_morse_well_depth_factor;

  // Capsule: a sphere with the normal RBC's volume (94.1 μm³) and membrane.
  CellKindConfig capsule = membrane_cell("capsule", CellShape::sphere, 1.0);
  capsule.diameter = capsule_diameter;

  return {normal, sickle, capsule};
}

const CellKindConfig* find_cell_kind(const CaseConfig& config, const std::string& name) {
  const auto found = std::find_if(config.cell_kinds.begin(), config.cell_kinds.end(),
                                  [&](const CellKindConfig& kind) { return kind.name == name; });
  return found == config.cell_kinds.end() ? nullptr : &*found;
}

MorseConfig morse_law_between(const CaseConfig& config, const CellKindConfig& a, const CellKindConfig& b) {
  const InteractionConfig& interaction = config.interaction;
  MorseConfig law = interaction.morse;
  law.well_depth *= std::sqrt(a.morse_well_depth_factor * b.morse_well_depth_factor);
  for (const MorsePairConfig& pair : interaction.pairs)
    if ((pair.kind_a == a.name && pair.kind_b == b.name) || (pair.kind_a == b.name && pair.kind_b == a.name))
      law = pair.morse;
  law.well_depth *= interaction.strength;
  return law;
}

double bulk_modulus_from_poisson(double shear_modulus, double poisson_ratio) {
  return 2.0 * shear_modulus * (1.0 + poisson_ratio) / (3.0 * (1.0 - 2.0 * poisson_ratio));
}

double poisson_from_bulk_modulus(double shear_modulus, double bulk_modulus) {
  return (3.0 * bulk_modulus - 2.0 * shear_modulus) / (2.0 * (3.0 * bulk_modulus + shear_modulus));
}

}  // namespace rouleau
