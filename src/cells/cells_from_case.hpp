#pragma once
// The cells of a case: each kind meshed once (through the mesh cache), each placement
// turned into a PlacedCell, all of them gathered into one CellPopulation on the device.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cells/cell_population.hpp"
#include "cells/surface_interaction.hpp"
#include "config/case_config.hpp"
#include "geometry/cell_mesh.hpp"

namespace rouleau {

struct CaseCells {
  std::map<std::string, CellMesh> meshes;  // per kind used, by kind name
  std::unique_ptr<CellPopulation> population;
  std::unique_ptr<SurfaceInteraction> interaction;  // when [interaction] is enabled
  SurfaceQuadrature quadrature = SurfaceQuadrature::nodes;  // the interaction's, as chosen
  // Per cell: how far the membrane's mid-surface lies inside the outer surface [μm], half
  // the shell thickness of a hollow shell (the thin membrane it stands for), 0 for a
  // filled body.
  std::vector<double> membrane_depth;
};

// The interaction's surface points for `choice`; "auto": nodes when the meshes' surface
// node spacing (the edge of the equilateral triangle of their mean triangle area) is at
// most the shortest 1/β of the laws, else 3 Gauss points per triangle.
SurfaceQuadrature surface_quadrature_for(InteractionQuadrature choice, const std::map<std::string, CellMesh>& meshes,
                                         const std::vector<MorsePotential>& potentials);

// The Morse law between every pair of the case's kinds, potentials[a * n + b] for kinds
// a, b (indices into config.cell_kinds): an [[interaction.pair]] entry's law when there is
// one, else [interaction]'s with De √(f_a f_b) (the kinds' morse_well_depth_factor); every
// De times strength_multiplier.
std::vector<MorsePotential> case_morse_potentials(const CaseConfig& config);

// Meshes every kind the case's cells use (from `mesh_cache_dir`), places the cells, and
// builds their interaction when it is enabled. The case must have passed
// check_cell_placement(). Returns empty pointers when the case has no cells.
CaseCells make_case_cells(const CaseConfig& config, const std::string& mesh_cache_dir);

}  // namespace rouleau
