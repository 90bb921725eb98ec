#pragma once
// The cells of a case: each kind meshed once (through the mesh cache), each placement
// turned into a PlacedCell, all of them gathered into one CellPopulation on the device.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cells/cell_population.hpp"
#include "config/case_config.hpp"
#include "geometry/cell_mesh.hpp"

namespace rouleau {

struct CaseCells {
  std::map<std::string, CellMesh> meshes;  // per kind used, by kind name
  std::unique_ptr<CellPopulation> population;
};

// Meshes every kind the case's cells use (from `mesh_cache_dir`) and places the cells.
// The case must have passed check_cell_placement(). Returns an empty population pointer
// when the case has no cells.
CaseCells make_case_cells(const CaseConfig& config, const std::string& mesh_cache_dir);

}  // namespace rouleau
