#pragma once
// Body-fitted tetrahedral meshes of the lumen of an axisymmetric vessel (vessel_profile.hpp)
// made with Gmsh, their boundary split into wall, inlet and outlet, cached on disk like
// the cell meshes. The axis is x, the inlet the disc at x = 0, the outlet the disc at x = L.
// Host-only: includes no Kokkos header.
#include <optional>
#include <string>
#include <vector>

#include "geometry/tetrahedral_mesh.hpp"
#include "geometry/vessel_profile.hpp"

namespace rouleau {

// Element sizes [μm]. At a point at distance r from the axis, where the lumen's radius is
// R(x), the size is
//   h(x, r) = (R(x)/R) [h_w + (h − h_w) min(1, 2 (R(x) − r)/R(x))]
// that is h_w on the wall growing linearly to h over the outer half of the radius, and
// scaled with the local radius so that a throat gets as many elements across as the feeders.
// A refined stretch [x_a, x_b] of the axis (where the cells squeeze) multiplies that size by
// s_r ≤ 1, returning to it linearly over a blend length ℓ = 2h on either side:
//   h_r(x, r) = h(x, r) [s_r + (1 − s_r) min(1, d(x)/ℓ)],  d(x) the distance from x to [x_a, x_b].
struct VesselMeshSizes {
  double element_size = 1.0;       // h, on the axis of the feeders
  double wall_element_size = 0.0;  // h_w, on the wall of the feeders; 0: the same as h
  double refined_scale = 1.0;      // s_r in (0, 1]; 1: no refined stretch
  double refined_from = 0.0;       // x_a [μm]
  double refined_to = 0.0;         // x_b [μm], ≥ x_a
};

// h_r(x, r) above [μm].
double vessel_element_size(const VesselProfile& profile, const VesselMeshSizes& sizes, double x, double r);

// The smallest element size the mesh is made for: h_r on the wall, minimized along the axis.
double smallest_vessel_element_size(const VesselProfile& profile, const VesselMeshSizes& sizes);

struct VesselMesh {
  std::vector<MeshPoint> nodes;             // [μm]
  std::vector<Tetrahedron> tetrahedra;      // positive volume
  // The boundary triangles, oriented out of the lumen, by surface: the inlet disc (x = 0),
  // the outlet disc (x = L) and the wall (the rest).
  std::vector<Triangle> inlet, outlet, wall;
  std::string hash;                         // of the parameters that made it (the cache key)
};

// What is wrong with the sizes, if anything: the key ("element_size_um",
// "wall_element_size_um", "refined_element_scale", "refined_to_um") and the reason (not
// positive; the wall size above the core size; a scale outside (0, 1]; a stretch that ends
// before it starts or lies outside the vessel; more than ~5 million elements expected).
std::optional<VesselProfileProblem> vessel_mesh_sizes_problem(const VesselProfile& profile,
                                                              const VesselMeshSizes& sizes);

// About the number of tetrahedra Gmsh makes of the lumen: ∫ dV / V_h(x, r), with
// V_h = h³/(6√2) the volume of the regular tetrahedron of the local element size h.
double expected_element_count(const VesselProfile& profile, const VesselMeshSizes& sizes);

// The mesh, from `cache_dir` when a mesh with the same hash is there, otherwise made with
// Gmsh and stored there. Throws std::runtime_error when the profile or sizes are refused or
// meshing fails.
VesselMesh vessel_mesh(const VesselProfile& profile, const VesselMeshSizes& sizes, const std::string& cache_dir);

// Meshes with Gmsh, bypassing the cache.
VesselMesh make_vessel_mesh(const VesselProfile& profile, const VesselMeshSizes& sizes);

}  // namespace rouleau
