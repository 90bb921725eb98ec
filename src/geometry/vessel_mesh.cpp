// Tetrahedral meshes of vessel lumens with Gmsh's OpenCASCADE kernel.
//
// Construction: the profile r(x) in the x–y half plane y ≥ 0 as a closed face: the inlet
// radius (0, 0)–(0, R), the wall (straight lines for the feeders and the throat; a cone
// transition as a line, a cosine one as a spline through transition_samples + 1 points of
// the exact curve), the outlet radius, and the axis back to the start. The face is
// revolved by 2π about x. Element sizes come from a size callback (VesselMeshSizes);
// surfaces by Frontal-Delaunay, volumes by Delaunay (deterministic, as for cells), Gmsh's
// default optimizer. The tetrahedra are oriented positively (an inverted or degenerate
// one, 6√2V/l³ < 1e-3, is an error), the nodes renumbered by reverse Cuthill–McKee (for
// the element loops' locality) and the tetrahedra put in canonical order; the boundary faces are
// those of one tetrahedron, oriented out of the lumen, and classified by position: all
// three nodes on the plane x = 0 (to 1e-9 of the vessel's size) is the inlet, on x = L
// the outlet, anything else the wall.
//
// Cache file (mesh_cache.hpp): cache_dir/vesselmesh-<hash>.txt, header
// "rouleau-vessel-mesh 1", surfaces inlet, outlet, wall.
#include "geometry/vessel_mesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "geometry/gmsh_session.hpp"
#include "geometry/mesh_cache.hpp"
#include "util/constants.hpp"

namespace rouleau {
namespace {

// Changes whenever this file would make a different mesh from the same parameters.
constexpr int vessel_code_version = 2;  // 2: nodes renumbered for locality
constexpr const char* cache_header = "rouleau-vessel-mesh 1";
// Points of the exact cosine curve a transition's spline passes through (the spline is
// then within ~1e-5 R of it).
constexpr int transition_samples = 32;
// Meshes expected to have more tetrahedra than this are refused (memory and time).
constexpr double largest_element_count = 5e6;

double wall_size(const VesselMeshSizes& sizes) {
  return sizes.wall_element_size > 0.0 ? sizes.wall_element_size : sizes.element_size;
}

// The refined stretch's factor s_r + (1 − s_r) min(1, d(x)/ℓ), ℓ = 2h.
double refinement_factor(const VesselMeshSizes& sizes, double x) {
  if (sizes.refined_scale >= 1.0) return 1.0;
  const double distance = std::max({sizes.refined_from - x, x - sizes.refined_to, 0.0});
  const double blend_length = 2.0 * sizes.element_size;
  return sizes.refined_scale + (1.0 - sizes.refined_scale) * std::min(1.0, distance / blend_length);
}

// The closed profile face in the x–y plane, revolved about x; within a GmshSession.
void add_lumen(const VesselProfile& p) {
  namespace occ = gmsh::model::occ;
  const double length = vessel_length(p);
  const int axis_start = occ::addPoint(0, 0, 0), axis_end = occ::addPoint(length, 0, 0);
  int current = occ::addPoint(0, p.radius, 0);
  std::vector<int> loop{occ::addLine(axis_start, current)};
  double x = 0.0;
  const auto straight = [&](double piece_length, double radius) {
    if (!(piece_length > 0.0)) return;
    x += piece_length;
    const int next = occ::addPoint(x, radius, 0);
    loop.push_back(occ::addLine(current, next));
    current = next;
  };
  const auto transition = [&](double piece_length, double to_radius) {
    if (!(piece_length > 0.0)) return;
    const double start = x;
    x += piece_length;
    const int next = occ::addPoint(x, to_radius, 0);
    if (p.transition == VesselTransition::cone) {
      loop.push_back(occ::addLine(current, next));
    } else {
      std::vector<int> points{current};
      for (int k = 1; k < transition_samples; ++k) {
        const double xk = start + piece_length * k / transition_samples;
        points.push_back(occ::addPoint(xk, vessel_radius(p, xk), 0));
      }
      points.push_back(next);
      loop.push_back(occ::addSpline(points));
    }
    current = next;
  };
  straight(p.inlet_length, p.radius);
  transition(p.contraction_length, p.throat_radius);
  straight(p.throat_length, p.throat_radius);
  transition(p.diffuser_length, p.radius);
  straight(p.outlet_length, p.radius);
  loop.push_back(occ::addLine(current, axis_end));
  loop.push_back(occ::addLine(axis_end, axis_start));
  const int face = occ::addPlaneSurface({occ::addCurveLoop(loop)});
  gmsh::vectorpair revolved;
  occ::revolve({{2, face}}, 0, 0, 0, 1, 0, 0, 2.0 * pi, revolved);
  occ::remove({{2, face}}, /*recursive=*/true);
  occ::synchronize();
}

TetrahedralMesh mesh_lumen(const VesselProfile& profile, const VesselMeshSizes& sizes) {
  GmshSession session;
  gmsh::model::add("vessel");
  add_lumen(profile);
  return mesh_volumes(std::max(sizes.element_size, wall_size(sizes)), [&](double x, double y, double z) {
    return vessel_element_size(profile, sizes, x, std::hypot(y, z));
  });
}

std::string describe(const VesselProfile& p) {
  std::ostringstream text;
  text << "the vessel (radius " << p.radius << " μm, throat " << p.throat_radius << " μm, length "
       << vessel_length(p) << " μm)";
  return text.str();
}

std::string canonical_parameters(const VesselProfile& p, const VesselMeshSizes& sizes) {
  std::ostringstream text;
  text.precision(17);
  text << "vessel_code=" << vessel_code_version << " gmsh=" << GmshSession::library_version()
       << " radius=" << p.radius << " throat_radius=" << p.throat_radius << " inlet_length=" << p.inlet_length
       << " contraction_length=" << p.contraction_length << " throat_length=" << p.throat_length
       << " diffuser_length=" << p.diffuser_length << " outlet_length=" << p.outlet_length
       << " transition=" << (p.transition == VesselTransition::cosine ? "cosine" : "cone")
       << " transition_samples=" << transition_samples << " element_size=" << sizes.element_size
       << " wall_element_size=" << wall_size(sizes);
  if (sizes.refined_scale < 1.0)  // absent otherwise: the meshes made before the option keep their hash
    text << " refined_scale=" << sizes.refined_scale << " refined_from=" << sizes.refined_from
         << " refined_to=" << sizes.refined_to;
  return text.str();
}

std::string cache_file_name(const std::string& hash) { return "vesselmesh-" + hash + ".txt"; }

const std::vector<std::pair<std::string, std::size_t>>& cached_surfaces() {
  static const std::vector<std::pair<std::string, std::size_t>> surfaces{{"inlet", 1}, {"outlet", 1}, {"wall", 1}};
  return surfaces;
}

// Throws std::runtime_error for a refused profile or sizes.
void check_input(const VesselProfile& profile, const VesselMeshSizes& sizes) {
  if (const auto problem = vessel_profile_problem(profile))
    throw std::runtime_error("vessel." + problem->key + ": " + problem->reason);
  if (const auto problem = vessel_mesh_sizes_problem(profile, sizes))
    throw std::runtime_error("vessel." + problem->key + ": " + problem->reason);
}

// Called after check_input().
VesselMesh make_vessel_mesh_with_parameters(const VesselProfile& profile, const VesselMeshSizes& sizes,
                                            const std::string& parameters) {
  TetrahedralMesh lumen;
  try {
    lumen = mesh_lumen(profile, sizes);
  } catch (...) {  // Gmsh 4.8 throws its error message as a std::string
    throw std::runtime_error(describe(profile) + ": Gmsh could not mesh it: " + current_gmsh_error());
  }
  if (lumen.tetrahedra.empty()) throw std::runtime_error(describe(profile) + ": Gmsh made no tetrahedra");
  require_valid_orientation(orient_tetrahedra(lumen.nodes, lumen.tetrahedra), describe(profile));
  renumber_nodes_for_locality(lumen.nodes, lumen.tetrahedra);
  canonicalize_tetrahedra(lumen.tetrahedra);
  VesselMesh mesh;
  const double length = vessel_length(profile), tolerance = 1e-9 * std::max(length, profile.radius);
  for (const Triangle& f : boundary_triangles(lumen.tetrahedra)) {
    const auto all_at = [&](double plane) {
      return std::abs(lumen.nodes[f[0]][0] - plane) < tolerance && std::abs(lumen.nodes[f[1]][0] - plane) < tolerance &&
             std::abs(lumen.nodes[f[2]][0] - plane) < tolerance;
    };
    (all_at(0.0) ? mesh.inlet : all_at(length) ? mesh.outlet : mesh.wall).push_back(f);
  }
  if (mesh.inlet.empty() || mesh.outlet.empty() || mesh.wall.empty())
    throw std::runtime_error(describe(profile) + ": the mesh's boundary lacks its inlet, outlet or wall");
  mesh.nodes = std::move(lumen.nodes);
  mesh.tetrahedra = std::move(lumen.tetrahedra);
  mesh.hash = fnv1a_hex(parameters);
  return mesh;
}

CachedMesh to_cached(const VesselMesh& mesh) {
  return {{mesh.nodes, mesh.tetrahedra}, {{"inlet", mesh.inlet}, {"outlet", mesh.outlet}, {"wall", mesh.wall}}};
}

}  // namespace

// h(x, r) = (R(x)/R) [h_w + (h − h_w) min(1, 2 (R(x) − r)/R(x))], times the refined
// stretch's factor.
double vessel_element_size(const VesselProfile& profile, const VesselMeshSizes& sizes, double x, double r) {
  const double local_radius = vessel_radius(profile, x);
  const double depth = std::clamp(2.0 * (local_radius - r) / local_radius, 0.0, 1.0);
  const double h_wall = wall_size(sizes);
  return local_radius / profile.radius * (h_wall + (sizes.element_size - h_wall) * depth) *
         refinement_factor(sizes, x);
}

double smallest_vessel_element_size(const VesselProfile& profile, const VesselMeshSizes& sizes) {
  const int samples = 2000;
  const double length = vessel_length(profile);
  double smallest = vessel_element_size(profile, sizes, 0.0, profile.radius);
  for (int i = 1; i <= samples; ++i) {
    const double x = length * i / samples;
    smallest = std::min(smallest, vessel_element_size(profile, sizes, x, vessel_radius(profile, x)));
  }
  return smallest;
}

double expected_element_count(const VesselProfile& profile, const VesselMeshSizes& sizes) {
  const int nx = 200, nr = 50;
  const double length = vessel_length(profile);
  double count = 0.0;
  for (int i = 0; i < nx; ++i) {
    const double x = (i + 0.5) * length / nx, radius = vessel_radius(profile, x);
    for (int j = 0; j < nr; ++j) {
      const double r = (j + 0.5) * radius / nr;
      const double h = vessel_element_size(profile, sizes, x, r);
      count += 2.0 * pi * r * (radius / nr) * (length / nx) / (h * h * h / 8.48528137423857029);
    }
  }
  return count;
}


std::optional<VesselProfileProblem> vessel_mesh_sizes_problem(const VesselProfile& profile,
                                                              const VesselMeshSizes& sizes) {
  if (!(sizes.element_size > 0.0) || !std::isfinite(sizes.element_size))
    return VesselProfileProblem{"element_size_um", "must be > 0"};
  if (!(sizes.wall_element_size >= 0.0) || !std::isfinite(sizes.wall_element_size))
    return VesselProfileProblem{"wall_element_size_um", "must be >= 0 (0: the same as element_size_um)"};
  if (wall_size(sizes) > sizes.element_size)
    return VesselProfileProblem{"wall_element_size_um", "must not exceed element_size_um (the mesh is graded toward the wall)"};
  if (!(sizes.refined_scale > 0.0 && sizes.refined_scale <= 1.0))
    return VesselProfileProblem{"refined_element_scale", "must be in (0, 1] (1: no refined stretch)"};
  if (sizes.refined_scale < 1.0) {
    if (!(sizes.refined_to > sizes.refined_from))
      return VesselProfileProblem{"refined_to_um", "must be above refined_from_um"};
    if (!(sizes.refined_from < vessel_length(profile) && sizes.refined_to > 0.0)) {
      std::ostringstream reason;
      reason << "the refined stretch must overlap the vessel, 0 to " << vessel_length(profile) << " μm";
      return VesselProfileProblem{"refined_to_um", reason.str()};
    }
  }
  if (!vessel_profile_problem(profile)) {
    const double count = expected_element_count(profile, sizes);
    if (count > largest_element_count) {
      std::ostringstream reason;
      reason.precision(3);
      reason << "about " << count << " tetrahedra expected, more than the " << largest_element_count
             << " allowed; choose larger elements";
      return VesselProfileProblem{"element_size_um", reason.str()};
    }
  }
  return std::nullopt;
}

VesselMesh make_vessel_mesh(const VesselProfile& profile, const VesselMeshSizes& sizes) {
  check_input(profile, sizes);
  return make_vessel_mesh_with_parameters(profile, sizes, canonical_parameters(profile, sizes));
}

VesselMesh vessel_mesh(const VesselProfile& profile, const VesselMeshSizes& sizes, const std::string& cache_dir) {
  check_input(profile, sizes);
  const std::string parameters = canonical_parameters(profile, sizes);
  const std::string hash = fnv1a_hex(parameters);
  CachedMesh cached =
      cached_or_made(cache_dir, cache_file_name(hash), cache_header, hash, parameters, cached_surfaces(),
                     describe(profile), [&] { return to_cached(make_vessel_mesh_with_parameters(profile, sizes, parameters)); });
  VesselMesh mesh;
  mesh.hash = hash;
  mesh.nodes = std::move(cached.mesh.nodes);
  mesh.tetrahedra = std::move(cached.mesh.tetrahedra);
  mesh.inlet = std::move(cached.surfaces[0].triangles);
  mesh.outlet = std::move(cached.surfaces[1].triangles);
  mesh.wall = std::move(cached.surfaces[2].triangles);
  return mesh;
}

}  // namespace rouleau
