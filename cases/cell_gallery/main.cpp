// The cell bodies side by side: runs cases/cell_gallery/case.toml (or the file given) and
// prints, for each kind used, its mesh and how close the meshed body is to the exact one.
//   case_cell_gallery [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cstdio>

#include "cells/cells_from_case.hpp"
#include "geometry/cell_shapes.hpp"
#include "config/cell_kinds.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/cell_gallery");
  if (!run.ran) return run.status;
  // What is special to this case: each cell's meshed volume and area against the exact body.
  const rouleau::CaseCells cells = rouleau::make_case_cells(run.config, rouleau::default_mesh_cache_dir());
  const auto measures = cells.population->measures();
  std::printf("%-16s %7s %7s %12s %12s %12s %12s\n", "kind", "nodes", "tets", "volume_um3", "exact", "area_um2",
              "exact");
  for (std::size_t c = 0; c < run.config.cells.size(); ++c) {
    const rouleau::CellKindConfig& kind = *rouleau::find_cell_kind(run.config, run.config.cells[c].kind);
    const rouleau::CellMesh& mesh = cells.meshes.at(kind.name);
    std::printf("%-16s %7zu %7zu %12.3f %12.3f %12.3f %12.3f\n", kind.name.c_str(), mesh.nodes.size(),
                mesh.tetrahedra.size(), measures[c].volume, rouleau::exact_cell_volume(kind), measures[c].area,
                rouleau::exact_cell_area(kind));
  }
  return 0;
}
