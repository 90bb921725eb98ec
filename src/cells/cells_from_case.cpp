#include "cells/cells_from_case.hpp"

#include <stdexcept>

#include "config/cell_kinds.hpp"
#include "geometry/cell_shapes.hpp"

namespace rouleau {

CaseCells make_case_cells(const CaseConfig& config, const std::string& mesh_cache_dir) {
  CaseCells result;
  if (config.cells.empty()) return result;
  std::vector<PlacedCell> placed;
  for (const CellPlacement& placement : config.cells) {
    const CellKindConfig* kind = find_cell_kind(config, placement.kind);
    if (!kind) throw std::logic_error("rouleau::make_case_cells: unknown cell kind " + placement.kind);
    auto mesh = result.meshes.find(kind->name);
    if (mesh == result.meshes.end()) mesh = result.meshes.emplace(kind->name, cell_mesh(*kind, mesh_cache_dir)).first;
    PlacedCell cell;
    cell.mesh = &mesh->second;
    cell.rotation = placement_rotation(placement);
    cell.center = placement.center;
    cell.material = NeoHookeanMaterial::from_moduli(kind->shear_modulus, kind->bulk_modulus);
    cell.kind = static_cast<int>(kind - config.cell_kinds.data());
    placed.push_back(cell);
  }
  result.population = std::make_unique<CellPopulation>(placed);
  return result;
}

}  // namespace rouleau
