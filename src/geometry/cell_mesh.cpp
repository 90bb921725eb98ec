// Tetrahedral meshes of the cell bodies, made with Gmsh's OpenCASCADE kernel, checked,
// and cached on disk.
//
// Constructions (body frame, centroid at the origin):
//   rbc     the Evans–Fung profile (cell_shape_details.hpp) in the x–z half plane x ≥ 0 as a
//           spline from the top of the axis over the rim to the bottom, closed by the axis
//           (filled) or by the inner profile, the outer one offset inward along its normal
//           by h, and two short pieces of the axis (shell); the face is revolved by 2π
//           about z.
//   sphere  an OpenCASCADE sphere; the shell is the sphere of radius R minus the one of
//           radius R − h.
//   spheroid  an OpenCASCADE unit sphere, its poles turned onto the longest axis (x for a
//           disc, left on z for a rod), scaled by (a, a, c); filled only (cell_shapes.cpp
//           says why).
//   sickle  the unbent ellipsoid (an OpenCASCADE unit sphere, its poles turned onto the x
//           axis, scaled by a, b, c; the shell minus the one with a − h, b − h, c − h) is
//           meshed with element sizes from the exact curvature, then every node is moved by
//           the bend map and centroid shift of cell_shapes.cpp. Its surface nodes lie on the
//           exact bent surface; the element edges are straight, as in any linear mesh.
// Element sizes: a size field from the exact curvature (ElementSizeField), surfaces by
// Frontal-Delaunay, volumes by Delaunay (deterministic), Gmsh's default optimizer.
// Then every tetrahedron is oriented positively (an inconsistently oriented or degenerate
// one, 6√2V/l³ < 1e-3, is an error), put in a canonical order, flat boundary caps are
// removed (peel_boundary_slivers), only nodes used by tetrahedra are kept, and the
// boundary faces (faces of one tetrahedron only) are oriented out of the solid and split
// into connected surfaces: the outer surface encloses the largest volume; a shell has one
// more, the cavity wall. Exactly one (filled) or two (shell) surfaces, or an error.
//
// Cache file (the format of mesh_cache.hpp), cache_dir/cellmesh-<hash>.txt, <hash> = 16
// hex digits of the 64-bit FNV-1a hash of the "parameters" line, header
// "rouleau-cell-mesh 1", surfaces outer_surface and inner_surface (empty for a filled body).
#include "geometry/cell_mesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "geometry/cell_shape_details.hpp"
#include "geometry/cell_shapes.hpp"
#include "geometry/gmsh_session.hpp"
#include "geometry/mesh_cache.hpp"
#include "geometry/tetrahedral_mesh.hpp"
#include "util/constants.hpp"

namespace rouleau {

using namespace geometry_detail;

namespace {

// Changes whenever this file would make a different mesh from the same parameters; it
// enters the hash, so old cache files are not reused.
constexpr int geometry_code_version = 2;
constexpr const char* cache_header = "rouleau-cell-mesh 1";

using Node = MeshPoint;  // a mesh node's position [μm]

// ---- element size presets
//
// Element sizes for a cell of the normal RBC's volume (D = 7.82 μm, 94.1 μm³); other
// cells are scaled by the cube root of their volume ratio (cell_element_size()), so that
// a cell of any size gets about the same number of nodes. Measured with Gmsh 4.8.4 for the
// normal RBC (nodes / tetrahedra, filled | shell h = 0.36 μm; smallest 6√2V/l³):
//   coarse  h = 1.0 μm    210 / 598     |  346 / 1060    (CI; faceting: V −4.7 %, A −2.6 %)
//   paper   h = 0.5 μm    1039 / 4014   |  1238 / 3767   (the paper: 1043 / 4567 filled;
//                                                         V −1.2 %, A −0.7 %)
//   fine    h = 0.25 μm   5983 / 28611  |  4831 / 14630  (V −0.3 %, A −0.2 %)
// Meshing takes 0.07 / 0.14 / 0.7 s (filled), 0.12 / 0.28 / 1.1 s (shell) on one core.
// The volume and area errors are those of any mesh of straight-edged elements with its
// nodes on a curved surface (the facets cut inside it): second order in h. Shells mesh
// fine with the element size well above the shell thickness (checked from 0.3 to 1.2 μm
// for h = 0.36 μm): Gmsh then puts one element across the layer.
double reference_cell_volume() {
  CellGeometry normal;
  normal.shape = CellShape::rbc;
  normal.body = CellBody::filled;
  normal.diameter = 7.82;
  static const double volume = exact_cell_volume(normal);  // 94.06 μm³
  return volume;
}
double reference_element_size(MeshResolution resolution) {
  switch (resolution) {
    case MeshResolution::coarse: return 1.0;
    case MeshResolution::paper: return 0.5;
    case MeshResolution::fine: return 0.25;
  }
  return 0.5;
}
// Elements per circle of the local curvature radius (ElementSizeField below): refines the
// sickle's tips and edges and, at the coarse preset, the RBC's rim, where the element size
// alone would cut corners.
int elements_per_curvature_circle(MeshResolution resolution) {
  switch (resolution) {
    case MeshResolution::coarse: return 6;
    case MeshResolution::paper: return 10;
    case MeshResolution::fine: return 20;
  }
  return 10;
}

// ---- geometry in Gmsh (OpenCASCADE kernel); call within a GmshSession

// A spline through the points (r, z) of the x–z half plane y = 0; returns its tag and the
// tags of its end points.
struct SplineTags {
  int curve, first, last;
};
SplineTags add_profile_spline(const std::vector<std::array<double, 2>>& profile) {
  std::vector<int> points;
  points.reserve(profile.size());
  for (const auto& p : profile) points.push_back(gmsh::model::occ::addPoint(p[0], 0.0, p[1]));
  return {gmsh::model::occ::addSpline(points), points.front(), points.back()};
}

void add_rbc(const CellGeometry& kind) {
  // Spline points every π/96 in θ: the interpolating spline is then within ~1e-6 R of
  // the profile.
  const int intervals = 96;
  const double radius = 0.5 * kind.diameter;
  std::vector<std::array<double, 2>> outer(intervals + 1);
  for (int k = 0; k <= intervals; ++k) outer[k] = rbc_profile_point(pi * k / intervals, radius);
  outer.front()[0] = outer.back()[0] = 0.0;
  const SplineTags outer_spline = add_profile_spline(outer);
  std::vector<int> loop;
  if (kind.body == CellBody::filled) {
    const int axis = gmsh::model::occ::addLine(outer_spline.last, outer_spline.first);
    loop = {outer_spline.curve, axis};
  } else {
    const SplineTags inner_spline = add_profile_spline(rbc_inner_profile(kind, intervals));
    const int bottom_axis = gmsh::model::occ::addLine(outer_spline.last, inner_spline.last);
    const int top_axis = gmsh::model::occ::addLine(inner_spline.first, outer_spline.first);
    loop = {outer_spline.curve, bottom_axis, inner_spline.curve, top_axis};
  }
  const int face = gmsh::model::occ::addPlaneSurface({gmsh::model::occ::addCurveLoop(loop)});
  gmsh::vectorpair revolved;
  gmsh::model::occ::revolve({{2, face}}, 0, 0, 0, 0, 0, 1, 2.0 * pi, revolved);
  gmsh::model::occ::remove({{2, face}}, /*recursive=*/true);
}

void add_sphere(const CellGeometry& kind) {
  const double radius = 0.5 * kind.diameter;
  const int outer = gmsh::model::occ::addSphere(0, 0, 0, radius);
  if (kind.body == CellBody::shell) {
    const int cavity = gmsh::model::occ::addSphere(0, 0, 0, radius - kind.shell_thickness);
    gmsh::vectorpair result;
    std::vector<gmsh::vectorpair> result_map;
    gmsh::model::occ::cut({{3, outer}}, {{3, cavity}}, result, result_map);
  }
}

// The ellipsoid with semi-axes a, b, c along x, y, z; for a shell minus the one with
// a − h, b − h, c − h.
void add_ellipsoid(const CellGeometry& kind, double a, double b, double c) {
  const auto add_solid = [](double a, double b, double c) {
    // The unit sphere's poles (on z) turned onto the longest axis before scaling, where
    // they become the tips: with the poles on the flat sides, Gmsh 4.8's surface mesher
    // fails on the scaled (B-spline) surface ("No elements in volume").
    const int tag = gmsh::model::occ::addSphere(0, 0, 0, 1.0);
    if (a >= b && a >= c) gmsh::model::occ::rotate({{3, tag}}, 0, 0, 0, 0, 1, 0, pi / 2);
    else if (b > a && b >= c) gmsh::model::occ::rotate({{3, tag}}, 0, 0, 0, 1, 0, 0, pi / 2);
    gmsh::model::occ::dilate({{3, tag}}, 0, 0, 0, a, b, c);
    return tag;
  };
  const int outer = add_solid(a, b, c);
  if (kind.body == CellBody::shell) {
    const double h = kind.shell_thickness;
    const int cavity = add_solid(a - h, b - h, c - h);
    gmsh::vectorpair result;
    std::vector<gmsh::vectorpair> result_map;
    gmsh::model::occ::cut({{3, outer}}, {{3, cavity}}, result, result_map);
  }
}

// The unbent ellipsoid (shell: minus its cavity); the nodes are bent after meshing.
void add_unbent_sickle(const CellGeometry& kind) {
  const SickleBend bend = sickle_bend(kind);
  add_ellipsoid(kind, bend.semi_length, bend.semi_width, bend.semi_thickness);
}

void add_spheroid(const CellGeometry& kind) {
  const SpheroidAxes axes = spheroid_axes(kind);
  add_ellipsoid(kind, axes.equatorial, axes.equatorial, axes.polar);
}

// ---- the element size field
//
// Element size at a point: s = min(h, max(h/4, 2π ρ / N)), with h the element size of the
// kind, ρ the smallest principal curvature radius of the exact outer surface near the
// point and N elements per curvature circle (per preset). Linear elements cut corners by
// about s²/(8ρ): this keeps that sag a fixed fraction of ρ where the surface is curved
// (the RBC's rim and dimple, the sickle's edges and tips) without refining flat parts.
// From the exact shape, not Gmsh's curvature estimate (which is noisy at the poles of
// surfaces of revolution and there made the surface mesher fall back to a far slower
// algorithm).
class ElementSizeField {
 public:
  ElementSizeField(const CellGeometry& kind, double element_size, int elements_per_circle)
      : kind_(kind), largest_(element_size), smallest_(0.25 * element_size),
        per_radius_(2.0 * pi / elements_per_circle) {
    if (kind.shape == CellShape::rbc) tabulate_rbc();
    if (kind.shape == CellShape::sickle) bend_ = sickle_bend(kind);
  }

  // Size at a point of the frame Gmsh meshes in (the sickle's unbent frame).
  double operator()(double x, double y, double z) const {
    return std::min(largest_, std::max(smallest_, per_radius_ * curvature_radius(x, y, z)));
  }

 private:
  double curvature_radius(double x, double y, double z) const {
    (void)z;
    switch (kind_.shape) {
      case CellShape::rbc: {
        // Linear in r between the tabulated radii.
        const double r = std::hypot(x, y);
        const auto above = std::lower_bound(radius_.begin(), radius_.end(), r);
        if (above == radius_.begin()) return radius_of_curvature_.front();
        if (above == radius_.end()) return radius_of_curvature_.back();
        const std::size_t k = above - radius_.begin();
        const double t = (r - radius_[k - 1]) / (radius_[k] - radius_[k - 1]);
        return radius_of_curvature_[k - 1] + t * (radius_of_curvature_[k] - radius_of_curvature_[k - 1]);
      }
      case CellShape::sphere: return 0.5 * kind_.diameter;
      case CellShape::spheroid: {
        // At the point of the meridian (a sin θ, c cos θ) with cos θ = z/c, the principal
        // curvature radii are, with s = a² cos²θ + c² sin²θ,
        //   meridional R_m = s^{3/2} / (a c),   circumferential R_c = a √s / c.
        const SpheroidAxes axes = spheroid_axes(kind_);
        const double a = axes.equatorial, c = axes.polar;
        const double cos_theta = std::clamp(z / c, -1.0, 1.0), sin2 = 1.0 - cos_theta * cos_theta;
        const double s = a * a * cos_theta * cos_theta + c * c * sin2;
        return std::min(s * std::sqrt(s) / (a * c), a * std::sqrt(s) / c);
      }
      case CellShape::sickle: {
        // Unbent ellipsoid: the cross-section at x is an ellipse with semi-axes b s, c s,
        // s = √(1 − x²/a²), whose smallest curvature radius is m² s / M (m, M the smaller
        // and larger of b, c); at the tips the meridians' is m²/a. The bend changes these
        // by at most the factor ρ/(ρ − b) on the inner side, covered by the preset's N.
        const double a = bend_.semi_length, m = std::min(bend_.semi_width, bend_.semi_thickness),
                     big = std::max(bend_.semi_width, bend_.semi_thickness);
        const double s = std::sqrt(std::max(0.0, 1.0 - (x / a) * (x / a)));
        return std::max(m * m * s / big, m * m / a);
      }
    }
    return largest_;
  }

  // Smallest principal curvature radius of the Evans–Fung surface against r, from the
  // profile's θ ∈ [0, π/2]: meridional κ_m = |r'z'' − z'r''| / |t|³ (t = (r', z'), its
  // derivative by central differences of the exact tangent), circumferential
  // κ_c = |z'| / (|t| r) (→ κ_m on the axis).
  void tabulate_rbc() {
    const int intervals = 400;
    const double radius = 0.5 * kind_.diameter, step = 1e-6;
    for (int k = 0; k <= intervals; ++k) {
      const double theta = 0.5 * pi * k / intervals;
      const auto t = rbc_profile_tangent(theta, radius);
      const auto t_after = rbc_profile_tangent(theta + step, radius), t_before = rbc_profile_tangent(theta - step, radius);
      const double r2 = (t_after[0] - t_before[0]) / (2 * step), z2 = (t_after[1] - t_before[1]) / (2 * step);
      const double speed = std::hypot(t[0], t[1]);
      const double meridional = std::abs(t[0] * z2 - t[1] * r2) / (speed * speed * speed);
      const double r = rbc_profile_point(theta, radius)[0];
      const double circumferential = k == 0 ? meridional : std::abs(t[1]) / (speed * r);
      radius_.push_back(r);
      radius_of_curvature_.push_back(1.0 / std::max({meridional, circumferential, 1e-12}));
    }
  }

  CellGeometry kind_;
  double largest_, smallest_, per_radius_;
  std::vector<double> radius_, radius_of_curvature_;  // rbc table
  SickleBend bend_{};
};

TetrahedralMesh mesh_with_gmsh(const CellGeometry& kind, double element_size) {
  GmshSession session;
  gmsh::model::add("cell");
  switch (kind.shape) {
    case CellShape::rbc: add_rbc(kind); break;
    case CellShape::sphere: add_sphere(kind); break;
    case CellShape::spheroid: add_spheroid(kind); break;
    case CellShape::sickle: add_unbent_sickle(kind); break;
  }
  gmsh::model::occ::synchronize();
  const ElementSizeField size_field(kind, element_size, elements_per_curvature_circle(kind.resolution));
  return mesh_volumes(element_size, [&size_field](double x, double y, double z) { return size_field(x, y, z); });
}

// ---- checks and surfaces

struct Surfaces {
  std::vector<Triangle> outer, inner;
};

// The boundary faces (used by one tetrahedron), oriented out of the solid, split into
// connected surfaces (sharing nodes). For a positive tetrahedron (0, 1, 2, 3) the faces
// seen from outside, counter-clockwise, are (0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2).
Surfaces boundary_surfaces(const CellGeometry& kind, const std::vector<Node>& nodes,
                           const std::vector<Tetrahedron>& tetrahedra) {
  std::vector<Triangle> boundary;
  try {
    boundary = boundary_triangles(tetrahedra);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(describe_kind(kind) + ": " + error.what());
  }

  // Connected surfaces: union–find over the nodes of the boundary faces.
  std::vector<int> parent(nodes.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& f : boundary) {
    parent[root(f[1])] = root(f[0]);
    parent[root(f[2])] = root(f[0]);
  }
  std::vector<int> roots;
  std::vector<std::vector<Triangle>> components;
  for (const auto& f : boundary) {
    const int r = root(f[0]);
    const auto found = std::find(roots.begin(), roots.end(), r);
    if (found == roots.end()) {
      roots.push_back(r);
      components.push_back({f});
    } else {
      components[found - roots.begin()].push_back(f);
    }
  }
  // The volume each encloses, by the divergence theorem: V = (1/6) Σ x0 · (x1 × x2) over
  // its faces (positive for normals pointing away from the enclosed region).
  std::vector<double> enclosed(components.size(), 0.0);
  for (std::size_t c = 0; c < components.size(); ++c)
    for (const auto& f : components[c]) enclosed[c] += signed_volume6({0, 0, 0}, nodes[f[0]], nodes[f[1]], nodes[f[2]]) / 6.0;
  const std::size_t expected = kind.body == CellBody::shell ? 2 : 1;
  if (components.size() != expected)
    throw std::runtime_error(describe_kind(kind) + ": the mesh has " + std::to_string(components.size()) +
                             " boundary surfaces, expected " + std::to_string(expected));
  std::size_t outer = 0;
  for (std::size_t c = 1; c < components.size(); ++c)
    if (std::abs(enclosed[c]) > std::abs(enclosed[outer])) outer = c;
  Surfaces surfaces;
  surfaces.outer = components[outer];
  if (!(enclosed[outer] > 0.0))
    throw std::runtime_error(describe_kind(kind) + ": the outer surface of the mesh encloses a negative volume");
  if (expected == 2) {
    const std::size_t inner = 1 - outer;
    surfaces.inner = components[inner];
    // Normals into the cavity, i.e. pointing toward the region it encloses: negative.
    if (!(enclosed[inner] < 0.0))
      throw std::runtime_error(describe_kind(kind) + ": the cavity wall of the mesh is not inside the solid");
  }
  return surfaces;
}

// ---- hashing and the cache

// The text every mesh-changing parameter goes into, one line, numbers to 17 digits.
std::string canonical_parameters(const CellGeometry& kind, double element_size) {
  std::ostringstream text;
  text.precision(17);
  text << "geometry_code=" << geometry_code_version << " gmsh=" << GmshSession::library_version();
  switch (kind.shape) {
    case CellShape::rbc: text << " shape=rbc diameter=" << kind.diameter; break;
    case CellShape::sphere: text << " shape=sphere diameter=" << kind.diameter; break;
    case CellShape::spheroid:
      text << " shape=spheroid diameter=" << kind.diameter << " axis_ratio=" << kind.axis_ratio;
      break;
    case CellShape::sickle:
      text << " shape=sickle length=" << kind.length << " width=" << kind.width << " thickness=" << kind.thickness
           << " arc_radius=" << kind.arc_radius;
      break;
  }
  if (kind.body == CellBody::shell) text << " body=shell shell_thickness=" << kind.shell_thickness;
  else text << " body=filled";
  text << " element_size=" << element_size
       << " curvature_elements=" << elements_per_curvature_circle(kind.resolution);
  return text.str();
}

std::string cache_file_name(const std::string& hash) { return "cellmesh-" + hash + ".txt"; }

// The cache file's surfaces: the outer surface, and the cavity wall (empty when filled).
std::vector<std::pair<std::string, std::size_t>> cached_surfaces(bool shell) {
  return {{"outer_surface", 4}, {"inner_surface", shell ? 4 : 0}};
}

CachedMesh to_cached(const CellMesh& mesh) {
  return {{mesh.nodes, mesh.tetrahedra}, {{"outer_surface", mesh.outer_surface}, {"inner_surface", mesh.inner_surface}}};
}

CellMesh from_cached(CachedMesh cached, const std::string& hash) {
  CellMesh mesh;
  mesh.hash = hash;
  mesh.nodes = std::move(cached.mesh.nodes);
  mesh.tetrahedra = std::move(cached.mesh.tetrahedra);
  mesh.outer_surface = std::move(cached.surfaces[0].triangles);
  mesh.inner_surface = std::move(cached.surfaces[1].triangles);
  return mesh;
}

CellMesh make_cell_mesh_with_parameters(const CellGeometry& kind, double element_size, const std::string& parameters) {
  validate_cell_kind(kind);
  if (!(element_size > 0.0 && std::isfinite(element_size)))
    throw std::runtime_error(describe_kind(kind) + ": the element size must be positive, not " + std::to_string(element_size));
  TetrahedralMesh raw;
  try {
    raw = mesh_with_gmsh(kind, element_size);
  } catch (...) {  // Gmsh 4.8 throws its error message as a std::string
    throw std::runtime_error(describe_kind(kind) + ": Gmsh could not mesh it (element size " +
                             std::to_string(element_size) + " μm): " + current_gmsh_error());
  }
  if (raw.tetrahedra.empty())
    throw std::runtime_error(describe_kind(kind) + ": Gmsh made no tetrahedra (element size " +
                             std::to_string(element_size) + " μm)");
  if (kind.shape == CellShape::sickle) {
    const SickleBend bend = sickle_bend(kind);
    for (auto& x : raw.nodes) x = bend_sickle_point(bend, x);
  }
  CellMesh mesh;
  mesh.nodes = std::move(raw.nodes);
  mesh.tetrahedra = std::move(raw.tetrahedra);
  require_valid_orientation(orient_tetrahedra(mesh.nodes, mesh.tetrahedra), describe_kind(kind));
  canonicalize_tetrahedra(mesh.tetrahedra);
  if (peel_boundary_slivers(mesh.nodes, mesh.tetrahedra) > 0) {
    drop_unused_nodes(mesh.nodes, mesh.tetrahedra);
    canonicalize_tetrahedra(mesh.tetrahedra);
  }
  Surfaces surfaces = boundary_surfaces(kind, mesh.nodes, mesh.tetrahedra);
  mesh.outer_surface = std::move(surfaces.outer);
  mesh.inner_surface = std::move(surfaces.inner);
  mesh.hash = fnv1a_hex(parameters);
  return mesh;
}

}  // namespace

double cell_element_size(const CellGeometry& kind) {
  if (kind.mesh_size > 0.0) return kind.mesh_size;
  // h = h_ref(resolution) · (V / V_ref)^{1/3}: similar node counts for any cell size.
  return reference_element_size(kind.resolution) * std::cbrt(exact_cell_volume(kind) / reference_cell_volume());
}

CellMesh make_cell_mesh(const CellGeometry& kind) {
  const double element_size = cell_element_size(kind);
  return make_cell_mesh_with_parameters(kind, element_size, canonical_parameters(kind, element_size));
}

CellMesh cell_mesh(const CellGeometry& kind, const std::string& cache_dir) {
  const double element_size = cell_element_size(kind);
  const std::string parameters = canonical_parameters(kind, element_size);
  const std::string hash = fnv1a_hex(parameters);
  const bool shell = kind.body == CellBody::shell;
  CachedMesh cached = cached_or_made(
      cache_dir, cache_file_name(hash), cache_header, hash, parameters, cached_surfaces(shell), describe_kind(kind),
      [&] { return to_cached(make_cell_mesh_with_parameters(kind, element_size, parameters)); },
      [&](const CachedMesh& read) {
        if (!shell && !read.surfaces[1].triangles.empty()) throw std::runtime_error("a filled body with a cavity wall");
      });
  return from_cached(std::move(cached), hash);
}

}  // namespace rouleau
