#include "cells/cells_from_case.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "config/cell_kinds.hpp"
#include "geometry/cell_shapes.hpp"

namespace rouleau {

std::vector<MorsePotential> case_morse_potentials(const CaseConfig& config) {
  const std::size_t n = config.cell_kinds.size();
  std::vector<MorsePotential> potentials(n * n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      const MorseConfig law = morse_law_between(config, config.cell_kinds[a], config.cell_kinds[b]);
      potentials[a * n + b] = MorsePotential{law.well_depth, law.beta, law.zero_force_length, law.cutoff};
    }
  return potentials;
}

SurfaceQuadrature surface_quadrature_for(InteractionQuadrature choice, const std::map<std::string, CellMesh>& meshes,
                                         const std::vector<MorsePotential>& potentials) {
  switch (choice) {
    case InteractionQuadrature::nodes: return SurfaceQuadrature::nodes;
    case InteractionQuadrature::gauss3: return SurfaceQuadrature::gauss3;
    case InteractionQuadrature::gauss6: return SurfaceQuadrature::gauss6;
    case InteractionQuadrature::automatic: break;
  }
  // The node spacing of a surface: the edge a of the equilateral triangle of its mean
  // triangle area A = (√3/4) a².
  double spacing = 0.0;
  for (const auto& [name, mesh] : meshes) {
    double area = 0.0;
    for (const auto& t : mesh.outer_surface) area += triangle_area(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]]);
    if (!mesh.outer_surface.empty())
      spacing = std::max(spacing, std::sqrt(4.0 * area / mesh.outer_surface.size() / std::sqrt(3.0)));
  }
  double range = 1e300;  // the shortest 1/β of the laws
  for (const MorsePotential& potential : potentials) range = std::min(range, 1.0 / potential.beta);
  return spacing > range ? SurfaceQuadrature::gauss3 : SurfaceQuadrature::nodes;
}

CaseCells make_case_cells(const CaseConfig& config, const std::string& mesh_cache_dir) {
  CaseCells result;
  if (config.cells.empty()) return result;
  std::vector<PlacedCell> placed;
  std::vector<int> cell_kind;
  for (const CellPlacement& placement : config.cells) {
    const CellKindConfig* kind = find_cell_kind(config, placement.kind);
    if (!kind) throw std::logic_error("rouleau::make_case_cells: unknown cell kind " + placement.kind);
    auto mesh = result.meshes.find(kind->name);
    if (mesh == result.meshes.end()) mesh = result.meshes.emplace(kind->name, cell_mesh(*kind, mesh_cache_dir)).first;
    PlacedCell cell;
    cell.mesh = &mesh->second;
    cell.rotation = placement_rotation(placement.orientation);
    cell.center = placement.center;
    cell.material =
        NeoHookeanMaterial::from_moduli(kind->shear_modulus, kind->bulk_modulus, kind->strain_hardening_ratio);
    cell.area_modulus = kind->area_modulus;
    cell.volume_modulus = kind->volume_modulus;
    cell.kind = static_cast<int>(kind - config.cell_kinds.data());
    placed.push_back(cell);
    cell_kind.push_back(cell.kind);
    result.membrane_depth.push_back(kind->body == CellBody::shell ? 0.5 * kind->shell_thickness : 0.0);
  }
  result.population = std::make_unique<CellPopulation>(placed);
  if (config.interaction.enabled) {
    const std::vector<MorsePotential> potentials = case_morse_potentials(config);
    result.quadrature = surface_quadrature_for(config.interaction.quadrature, result.meshes, potentials);
    result.interaction = std::make_unique<SurfaceInteraction>(*result.population, cell_kind,
                                                              static_cast<int>(config.cell_kinds.size()), potentials,
                                                              config.interaction.skin, true, result.quadrature);
  }
  return result;
}

}  // namespace rouleau
