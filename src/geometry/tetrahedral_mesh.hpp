#pragma once
// What the Gmsh meshers of cells (cell_mesh) and vessels (vessel_mesh) share: reading the
// linear tetrahedra Gmsh made, orienting and checking them, a canonical order (the same
// mesh every run), removing flat boundary slivers, and the boundary triangles.
// Host-only: includes no Kokkos header.
#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rouleau {

using MeshPoint = std::array<double, 3>;
using Tetrahedron = std::array<int, 4>;
using Triangle = std::array<int, 3>;

struct TetrahedralMesh {
  std::vector<MeshPoint> nodes;
  std::vector<Tetrahedron> tetrahedra;
};

// The linear tetrahedra of the current Gmsh model and the nodes they use, numbered in
// Gmsh's tag order. Call within a GmshSession, after mesh::generate(3).
TetrahedralMesh gmsh_tetrahedra();

// Meshes the volumes of the current Gmsh model (within a GmshSession, after synchronize())
// with linear tetrahedra of size size(x, y, z), at most largest_size: surfaces by
// Frontal-Delaunay, volumes by Delaunay (the same mesh every run; HXT, of better quality,
// returns different tetrahedra from run to run even on one thread), Gmsh's default
// optimizer. Returns gmsh_tetrahedra().
TetrahedralMesh mesh_volumes(double largest_size, const std::function<double(double, double, double)>& size);

// 6 V = (x1 − x0) · ((x2 − x0) × (x3 − x0))
double signed_volume6(const MeshPoint& x0, const MeshPoint& x1, const MeshPoint& x2, const MeshPoint& x3);

// 6√2 V / l_max³: 1 for the regular tetrahedron, → 0 for a flat one, < 0 when inverted.
double tetrahedron_quality(const std::vector<MeshPoint>& nodes, const Tetrahedron& t);

// Below this quality a tetrahedron counts as degenerate.
inline constexpr double degenerate_quality = 1e-3;

// Orients a consistently oriented mesh positively (all volumes of one sign: flipped when
// most are negative) and counts what is left wrong: tetrahedra of the other sign
// (inverted) and of quality below degenerate_quality.
struct OrientationReport {
  std::size_t inverted = 0, degenerate = 0;
  double worst_quality = 0.0;
};
OrientationReport orient_tetrahedra(const std::vector<MeshPoint>& nodes, std::vector<Tetrahedron>& tetrahedra);

// Throws std::runtime_error "<what>: the mesh has I inverted and D degenerate tetrahedra
// (worst quality …)" when the report counts any.
void require_valid_orientation(const OrientationReport& report, const std::string& what);

// Canonical form: each tetrahedron's vertices ascending up to an even permutation (the
// orientation stays), the tetrahedra sorted. Gmsh may return the same tetrahedra in
// another order; then the mesh, its surfaces and cache files are the same every time.
void canonicalize_tetrahedra(std::vector<Tetrahedron>& tetrahedra);

// Removes flat tetrahedra (quality < 0.1) with two faces on the boundary, an edge flip of
// the surface triangulation whose nodes all stay on the exact surface (see the .cpp).
// Returns how many; call drop_unused_nodes() and canonicalize_tetrahedra() after.
std::size_t peel_boundary_slivers(const std::vector<MeshPoint>& nodes, std::vector<Tetrahedron>& tetrahedra);

// Renumbers the nodes by reverse Cuthill–McKee on the graph of the tetrahedra's edges
// (breadth-first from a pseudo-peripheral node, neighbours by increasing degree, the order
// reversed), so that nodes close in the mesh are close in memory: element loops then
// gather from a narrow band. Deterministic (ties go to the lower old index). Call
// canonicalize_tetrahedra() after, which orders the elements by their nodes.
void renumber_nodes_for_locality(std::vector<MeshPoint>& nodes, std::vector<Tetrahedron>& tetrahedra);

// Keeps only the nodes some tetrahedron uses, in their order.
void drop_unused_nodes(std::vector<MeshPoint>& nodes, std::vector<Tetrahedron>& tetrahedra);

// The faces used by one tetrahedron only, oriented out of the mesh (counter-clockwise seen
// from outside), each turned to start at its smallest node, in a canonical order. Throws
// std::runtime_error when a face is shared by more than two tetrahedra.
std::vector<Triangle> boundary_triangles(const std::vector<Tetrahedron>& tetrahedra);

// FNV-1a, 64 bits, as 16 hex digits: the hash of a mesher's parameter text.
std::string fnv1a_hex(const std::string& text);

}  // namespace rouleau
