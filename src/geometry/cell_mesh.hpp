#pragma once
// Finite-element meshes of cells (4-node tetrahedra) made with Gmsh, in the body frame of
// their kind, and cached on disk by a hash of everything that made them.
// Host-only: includes no Kokkos header.
#include <array>
#include <string>
#include <vector>

#include "geometry/cell_geometry.hpp"
#include "geometry/mesh_cache.hpp"  // default_mesh_cache_dir()

namespace rouleau {

// A cell's mesh in its body frame: the body's centroid at the origin; RBC and sphere axis
// along z; sickle centre line in the x–y plane.
struct CellMesh {
  std::vector<std::array<double, 3>> nodes;     // [μm]
  std::vector<std::array<int, 4>> tetrahedra;   // positive volume: (x1−x0)·((x2−x0)×(x3−x0)) > 0
  // The surface seen from outside (where the Morse interaction acts), counter-clockwise
  // seen from outside (normals point out of the cell).
  std::vector<std::array<int, 3>> outer_surface;
  // Shell bodies only: the cavity wall, normals pointing into the cavity (out of the solid).
  std::vector<std::array<int, 3>> inner_surface;
  // Hex digest of the parameters that made it (shape, body, sizes, element size, mesher
  // version): the cache key, and the "mesh hash" of the provenance.
  std::string hash;
};

// The mesh of `kind` (its shape, body, sizes, resolution and mesh_size; the material does
// not enter), read from `cache_dir` when a mesh with the same hash is there, otherwise made
// with Gmsh and stored there (written to a temporary name and renamed). A cached file that
// cannot be read is remade. Throws std::runtime_error naming the kind when meshing fails.
CellMesh cell_mesh(const CellGeometry& kind, const std::string& cache_dir);

// Meshes `kind` with Gmsh, bypassing the cache.
CellMesh make_cell_mesh(const CellGeometry& kind);

// The element size [μm] `kind` is meshed with: mesh_size when > 0, else its preset.
double cell_element_size(const CellGeometry& kind);

}  // namespace rouleau
