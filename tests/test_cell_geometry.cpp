// Cell shapes and their Gmsh meshes (src/geometry): the Evans–Fung profile and exact
// integrals, meshed volumes and areas against them, mesh validity (orientation, quality,
// closed oriented surfaces), the mesh cache, and the placement check of a case's cells.
// Host-only code: nothing here needs Kokkos.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "config/cell_kinds.hpp"
#include "config/cell_placement_check.hpp"
#include "geometry/cell_mesh.hpp"
#include "geometry/cell_shape_details.hpp"
#include "geometry/cell_shapes.hpp"
#include "util/errors.hpp"

namespace {

using namespace rouleau;
namespace fs = std::filesystem;
using Vector3 = std::array<double, 3>;

constexpr double pi = 3.14159265358979323846;

// ---- kinds

CellKindConfig rbc_kind(CellBody body, MeshResolution resolution) {
  CellKindConfig kind;
  kind.name = "normal";
  kind.shape = CellShape::rbc;
  kind.body = body;
  kind.diameter = 7.82;
  kind.shell_thickness = 0.36;
  kind.resolution = resolution;
  return kind;
}
CellKindConfig sphere_kind(CellBody body, MeshResolution resolution) {
  CellKindConfig kind = rbc_kind(body, resolution);
  kind.name = "capsule";
  kind.shape = CellShape::sphere;
  kind.diameter = 5.64;
  return kind;
}
CellKindConfig sickle_kind(CellBody body, MeshResolution resolution) {
  CellKindConfig kind = rbc_kind(body, resolution);
  kind.name = "sickle";
  kind.shape = CellShape::sickle;
  kind.length = 14.0;
  kind.width = 4.2;
  kind.thickness = 3.0;
  kind.arc_radius = 8.0;
  return kind;
}
// A spheroid with the equatorial diameter 7.82 μm of the normal RBC and polar/equatorial
// semi-axes `axis_ratio`.
CellKindConfig spheroid_kind(CellBody body, MeshResolution resolution, double axis_ratio) {
  CellKindConfig kind = rbc_kind(body, resolution);
  kind.name = axis_ratio < 1.0 ? "oblate" : "prolate";
  kind.shape = CellShape::spheroid;
  kind.axis_ratio = axis_ratio;
  return kind;
}
// (x² + y²)/a² + z²/c² − 1 of a spheroid kind at p (0 on its surface).
double spheroid_level(const CellKindConfig& kind, const Vector3& p) {
  const double a = 0.5 * kind.diameter, c = a * kind.axis_ratio;
  return (p[0] * p[0] + p[1] * p[1]) / (a * a) + p[2] * p[2] / (c * c) - 1.0;
}
const char* body_name(CellBody body) { return body == CellBody::shell ? "shell" : "filled"; }
const char* resolution_name(MeshResolution resolution) {
  return resolution == MeshResolution::coarse ? "coarse" : resolution == MeshResolution::paper ? "paper" : "fine";
}

// ---- measures of a mesh

Vector3 minus(const Vector3& a, const Vector3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vector3& a, const Vector3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vector3& a) { return std::sqrt(dot(a, a)); }

// V = (x1 − x0) · ((x2 − x0) × (x3 − x0)) / 6
double tetrahedron_volume(const CellMesh& mesh, const std::array<int, 4>& t) {
  const auto& x = mesh.nodes;
  return dot(minus(x[t[1]], x[t[0]]), cross(minus(x[t[2]], x[t[0]]), minus(x[t[3]], x[t[0]]))) / 6.0;
}
// Divergence theorem: the volume a closed surface encloses, V = (1/6) Σ x0 · (x1 × x2)
// (positive when the normals point away from it).
double enclosed_volume(const CellMesh& mesh, const std::vector<std::array<int, 3>>& surface) {
  double volume = 0.0;
  for (const auto& f : surface) volume += dot(mesh.nodes[f[0]], cross(mesh.nodes[f[1]], mesh.nodes[f[2]])) / 6.0;
  return volume;
}
// Centroid of the enclosed volume: sum over the cones (origin, face) of their volume times
// their centroid (x0 + x1 + x2)/4, over the total.
Vector3 enclosed_centroid(const CellMesh& mesh, const std::vector<std::array<int, 3>>& surface) {
  Vector3 moment{0, 0, 0};
  double volume = 0.0;
  for (const auto& f : surface) {
    const double cone = dot(mesh.nodes[f[0]], cross(mesh.nodes[f[1]], mesh.nodes[f[2]])) / 6.0;
    volume += cone;
    for (int d = 0; d < 3; ++d) moment[d] += cone * (mesh.nodes[f[0]][d] + mesh.nodes[f[1]][d] + mesh.nodes[f[2]][d]) / 4.0;
  }
  return {moment[0] / volume, moment[1] / volume, moment[2] / volume};
}
// A = Σ |(x1 − x0) × (x2 − x0)| / 2
double surface_area(const CellMesh& mesh, const std::vector<std::array<int, 3>>& surface) {
  double area = 0.0;
  for (const auto& f : surface)
    area += 0.5 * norm(cross(minus(mesh.nodes[f[1]], mesh.nodes[f[0]]), minus(mesh.nodes[f[2]], mesh.nodes[f[0]])));
  return area;
}
// 6√2 V / l_max³: 1 for a regular tetrahedron.
double tetrahedron_quality(const CellMesh& mesh, const std::array<int, 4>& t) {
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) longest = std::max(longest, norm(minus(mesh.nodes[t[i]], mesh.nodes[t[j]])));
  return 6.0 * std::sqrt(2.0) * tetrahedron_volume(mesh, t) / (longest * longest * longest);
}

struct MeshReport {
  double solid_volume = 0, enclosed_volume = 0, outer_area = 0, cavity_volume = 0, inner_area = 0;
  double min_quality = 1e300, mean_quality = 0;
  std::size_t non_positive = 0;
};
MeshReport measure(const CellMesh& mesh) {
  MeshReport report;
  for (const auto& t : mesh.tetrahedra) {
    const double volume = tetrahedron_volume(mesh, t);
    report.solid_volume += volume;
    if (!(volume > 0.0)) ++report.non_positive;
    const double quality = tetrahedron_quality(mesh, t);
    report.min_quality = std::min(report.min_quality, quality);
    report.mean_quality += quality / mesh.tetrahedra.size();
  }
  report.enclosed_volume = enclosed_volume(mesh, mesh.outer_surface);
  report.outer_area = surface_area(mesh, mesh.outer_surface);
  report.cavity_volume = -enclosed_volume(mesh, mesh.inner_surface);
  report.inner_area = surface_area(mesh, mesh.inner_surface);
  return report;
}

// Closed, manifold and consistently oriented: every directed edge of the triangles occurs
// once and its reverse once (so each undirected edge is shared by exactly two triangles,
// traversed in opposite directions). Returns the Euler characteristic V − E + F.
int check_closed_oriented_surface(const std::vector<std::array<int, 3>>& surface, const char* which) {
  std::map<std::pair<int, int>, int> directed;
  std::set<int> nodes;
  for (const auto& f : surface)
    for (int k = 0; k < 3; ++k) {
      ++directed[{f[k], f[(k + 1) % 3]}];
      nodes.insert(f[k]);
    }
  std::size_t bad = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0u) << which << " surface: edges not shared by exactly two oppositely oriented triangles";
  const long edges = static_cast<long>(directed.size() / 2);
  return static_cast<int>(static_cast<long>(nodes.size()) - edges + static_cast<long>(surface.size()));
}

// Checks every mesh must pass, whatever its shape.
void expect_valid_mesh(const CellKindConfig& kind, const CellMesh& mesh, const MeshReport& report) {
  EXPECT_EQ(report.non_positive, 0u) << "tetrahedra without positive volume";
  // The presets' meshes stay above 0.05 in 6√2V/l³ (the lowest are in the shells, one
  // element across the layer); a sliver (≈ 0) or an inverted element would fail here.
  EXPECT_GT(report.min_quality, 0.04);
  EXPECT_GT(report.mean_quality, 0.3);
  // Every node is used by a tetrahedron (renumbered).
  std::vector<char> used(mesh.nodes.size(), 0);
  for (const auto& t : mesh.tetrahedra)
    for (int v : t) {
      ASSERT_GE(v, 0);
      ASSERT_LT(v, static_cast<int>(mesh.nodes.size()));
      used[v] = 1;
    }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "nodes not used by any tetrahedron";
  EXPECT_EQ(check_closed_oriented_surface(mesh.outer_surface, "outer"), 2) << "outer surface is not a sphere";
  EXPECT_GT(report.enclosed_volume, 0.0) << "outer surface normals point inward";
  if (kind.body == CellBody::shell) {
    EXPECT_EQ(check_closed_oriented_surface(mesh.inner_surface, "inner"), 2) << "cavity wall is not a sphere";
    EXPECT_GT(report.cavity_volume, 0.0) << "cavity wall normals do not point into the cavity";
    // The shell's solid is what lies between its two surfaces.
    EXPECT_NEAR(report.solid_volume, report.enclosed_volume - report.cavity_volume, 1e-9 * report.enclosed_volume);
  } else {
    EXPECT_TRUE(mesh.inner_surface.empty());
    EXPECT_NEAR(report.solid_volume, report.enclosed_volume, 1e-9 * report.enclosed_volume);
  }
  EXPECT_EQ(mesh.hash.size(), 16u);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Meshes `kind`, checks it is valid, prints counts, errors against the exact integrals,
// quality and time.
struct MeshedCell {
  CellMesh mesh;
  MeshReport report;
  double volume_error = 0, area_error = 0;  // relative, of the outer surface
};
MeshedCell mesh_and_report(const CellKindConfig& kind) {
  const auto start = std::chrono::steady_clock::now();
  MeshedCell cell;
  cell.mesh = make_cell_mesh(kind);
  const double time = seconds_since(start);
  cell.report = measure(cell.mesh);
  const double exact_volume = exact_cell_volume(kind), exact_area = exact_cell_area(kind);
  cell.volume_error = (cell.report.enclosed_volume - exact_volume) / exact_volume;
  cell.area_error = (cell.report.outer_area - exact_area) / exact_area;
  std::cout << "  " << kind.name << " " << body_name(kind.body) << " " << resolution_name(kind.resolution)
            << " (element size " << cell_element_size(kind) << " μm): " << cell.mesh.nodes.size() << " nodes, "
            << cell.mesh.tetrahedra.size() << " tetrahedra, " << cell.mesh.outer_surface.size() << " outer + "
            << cell.mesh.inner_surface.size() << " inner triangles; enclosed volume " << cell.report.enclosed_volume
            << " (exact " << exact_volume << ", " << 100 * cell.volume_error << " %), outer area "
            << cell.report.outer_area << " (exact " << exact_area << ", " << 100 * cell.area_error
            << " %), solid volume " << cell.report.solid_volume << ", quality min " << cell.report.min_quality
            << " mean " << cell.report.mean_quality << ", meshed in " << time << " s\n";
  expect_valid_mesh(kind, cell.mesh, cell.report);
  return cell;
}

// A fresh directory for one test's cache, removed at the end.
class TemporaryDirectory {
 public:
  explicit TemporaryDirectory(const std::string& tag)
      : path_(fs::temp_directory_path() / ("rouleau-test-" + tag + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Distance from (r, z) to a polyline in the (r, z) plane.
double distance_to_polyline(const std::vector<std::array<double, 2>>& line, double r, double z) {
  double best = INFINITY;
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {
    const double dr = line[k + 1][0] - line[k][0], dz = line[k + 1][1] - line[k][1];
    const double length2 = dr * dr + dz * dz;
    const double t =
        length2 > 0 ? std::clamp(((r - line[k][0]) * dr + (z - line[k][1]) * dz) / length2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(r - line[k][0] - t * dr, z - line[k][1] - t * dz));
  }
  return best;
}
std::vector<std::array<double, 2>> exact_rbc_profile(double radius, int intervals) {
  std::vector<std::array<double, 2>> profile(intervals + 1);
  for (int k = 0; k <= intervals; ++k) profile[k] = geometry_detail::rbc_profile_point(pi * k / intervals, radius);
  return profile;
}
// Largest distance of the surface's nodes from the revolved profile.
double largest_distance_from_profile(const CellMesh& mesh, const std::vector<std::array<int, 3>>& surface,
                                     const std::vector<std::array<double, 2>>& profile) {
  std::set<int> nodes;
  for (const auto& f : surface) nodes.insert(f.begin(), f.end());
  double largest = 0.0;
  for (int i : nodes) {
    const auto& x = mesh.nodes[i];
    largest = std::max(largest, distance_to_polyline(profile, std::hypot(x[0], x[1]), x[2]));
  }
  return largest;
}
// Volume enclosed by revolving a closed-by-the-axis profile polyline: Σ π (r0² + r0 r1 +
// r1²)/3 · |Δz| (each segment a frustum; exact for the polyline).
double revolved_volume(const std::vector<std::array<double, 2>>& profile) {
  double volume = 0.0;
  for (std::size_t k = 0; k + 1 < profile.size(); ++k) {
    const double r0 = profile[k][0], r1 = profile[k + 1][0];
    volume -= pi * (r0 * r0 + r0 * r1 + r1 * r1) / 3.0 * (profile[k + 1][1] - profile[k][1]);
  }
  return volume;
}

// ---- the Evans–Fung profile and the exact integrals

TEST(CellShapes, EvansFungProfileMatchesThePaperNumbers) {
  const double diameter = 7.82, radius = 0.5 * diameter;
  double largest_half_thickness = 0.0;
  for (int k = 0; k <= 100000; ++k)
    largest_half_thickness = std::max(largest_half_thickness, evans_fung_half_thickness(radius * k / 100000.0, radius));
  const double centre = 2.0 * evans_fung_half_thickness(0.0, radius);
  const CellKindConfig kind = rbc_kind(CellBody::filled, MeshResolution::paper);
  const double volume = exact_cell_volume(kind), area = exact_cell_area(kind);
  std::cout << "  Evans–Fung D = 7.82 μm: max thickness " << 2 * largest_half_thickness << " μm, centre " << centre
            << " μm, V = " << volume << " μm³, A = " << area << " μm²\n";
  EXPECT_NEAR(2 * largest_half_thickness, 2.57, 0.01);
  EXPECT_NEAR(centre, 0.81, 0.01);
  EXPECT_NEAR(volume, 94.1, 0.2);
  EXPECT_NEAR(area, 134.1, 0.2);
  // The shell's exact integrals are those of the outer surface.
  EXPECT_DOUBLE_EQ(exact_cell_volume(rbc_kind(CellBody::shell, MeshResolution::paper)), volume);
  // The angle parametrization is the same curve: z(θ) = ±R y(r(θ)/R), r(θ) = R sin θ.
  for (int k = 0; k <= 50; ++k) {
    const auto point = geometry_detail::rbc_profile_point(pi * k / 50, radius);
    EXPECT_NEAR(std::abs(point[1]), evans_fung_half_thickness(point[0], radius), 1e-12);
  }
  // A cruder check of the quadratures: trapezoidal sums in r on a fine grid.
  double trapezoid_volume = 0.0;
  const int steps = 200000;
  for (int k = 0; k < steps; ++k) {
    const double r0 = radius * k / steps, r1 = radius * (k + 1) / steps;
    trapezoid_volume += 0.5 * (2 * pi * r0 * 2 * evans_fung_half_thickness(r0, radius) +
                               2 * pi * r1 * 2 * evans_fung_half_thickness(r1, radius)) * (r1 - r0);
  }
  EXPECT_NEAR(trapezoid_volume, volume, 1e-4 * volume);
  // Scaling: V ∝ D³, A ∝ D².
  CellKindConfig larger = kind;
  larger.diameter = 2 * diameter;
  EXPECT_NEAR(exact_cell_volume(larger), 8 * volume, 1e-9 * volume);
  EXPECT_NEAR(exact_cell_area(larger), 4 * area, 1e-9 * area);
}

TEST(CellShapes, SphereAndSickleExactIntegrals) {
  const CellKindConfig sphere = sphere_kind(CellBody::filled, MeshResolution::paper);
  const double radius = 0.5 * sphere.diameter;
  EXPECT_NEAR(exact_cell_volume(sphere), 4.0 / 3.0 * pi * radius * radius * radius, 1e-12);
  EXPECT_NEAR(exact_cell_area(sphere), 4.0 * pi * radius * radius, 1e-12);

  // A sickle bent along a huge arc is the unbent prolate spheroid (b = c): its area
  // 2πb² (1 + a/(b e) asin e), e = √(1 − b²/a²), checks the surface quadrature.
  CellKindConfig straight = sickle_kind(CellBody::filled, MeshResolution::paper);
  straight.width = straight.thickness = 3.0;
  straight.arc_radius = 1e7;
  const double a = 7.0, b = 1.5, e = std::sqrt(1 - b * b / (a * a));
  const double spheroid_area = 2 * pi * b * b * (1 + a / (b * e) * std::asin(e));
  EXPECT_NEAR(exact_cell_area(straight), spheroid_area, 1e-6 * spheroid_area);

  const CellKindConfig sickle = sickle_kind(CellBody::filled, MeshResolution::paper);
  const double ellipsoid_volume = 4.0 / 3.0 * pi * 7.0 * 2.1 * 1.5;
  const double sickle_area = exact_cell_area(sickle);
  std::cout << "  sickle 14 × 4.2 × 3 μm on an 8 μm arc: V = " << exact_cell_volume(sickle) << " μm³, A = " << sickle_area
            << " μm²\n";
  EXPECT_NEAR(exact_cell_volume(sickle), ellipsoid_volume, 1e-12);
  EXPECT_NEAR(exact_cell_volume(sickle), 92.0, 0.5);
}

TEST(CellShapes, SpheroidExactIntegralsAndInside) {
  // The closed forms of cell_shapes.cpp against an independent quadrature of the surface of
  // revolution, A = ∫₀^π 2π a sin θ √(a² cos²θ + c² sin²θ) dθ (midpoint rule, 20000
  // intervals), and the volume against a count of inside_cell on a 0.05 μm grid.
  for (const double ratio : {0.25, 1.0 / 3.0, 1.0, 2.0, 4.0}) {
    const CellKindConfig kind = spheroid_kind(CellBody::filled, MeshResolution::paper, ratio);
    const double a = 0.5 * kind.diameter, c = ratio * a;
    double area = 0.0;
    const int intervals = 20000;
    for (int k = 0; k < intervals; ++k) {
      const double theta = pi * (k + 0.5) / intervals, st = std::sin(theta), ct = std::cos(theta);
      area += 2.0 * pi * a * st * std::sqrt(a * a * ct * ct + c * c * st * st) * pi / intervals;
    }
    EXPECT_NEAR(exact_cell_area(kind), area, 1e-6 * area) << "axis ratio " << ratio;
    EXPECT_NEAR(exact_cell_volume(kind), 4.0 / 3.0 * pi * a * a * c, 1e-12 * a * a * c);
    const double step = 0.05;
    long inside = 0;
    for (double x = -a + 0.5 * step; x < a; x += step)
      for (double y = -a + 0.5 * step; y < a; y += step)
        for (double z = -c + 0.5 * step; z < c; z += step) inside += inside_cell(kind, {x, y, z});
    const double counted = inside * step * step * step;
    std::cout << "  spheroid c/a = " << ratio << ": A = " << exact_cell_area(kind) << " μm² (quadrature " << area
              << "), V = " << exact_cell_volume(kind) << " μm³ (grid count " << counted << ")\n";
    EXPECT_NEAR(counted, exact_cell_volume(kind), 0.01 * exact_cell_volume(kind));
  }
  // Axis ratio 1 is the sphere of that diameter.
  const CellKindConfig round = spheroid_kind(CellBody::filled, MeshResolution::paper, 1.0);
  CellKindConfig sphere = round;
  sphere.shape = CellShape::sphere;
  EXPECT_DOUBLE_EQ(exact_cell_area(round), exact_cell_area(sphere));
  EXPECT_DOUBLE_EQ(exact_cell_volume(round), exact_cell_volume(sphere));
  // Not positive: refused.
  CellKindConfig flat = round;
  flat.axis_ratio = 0.0;
  EXPECT_THROW(exact_cell_volume(flat), std::runtime_error);
}

TEST(CellShapes, SickleBendKeepsTheVolumeAndCentresIt) {
  // Count the body's volume on a grid with inside_cell (which inverts the bend map): it
  // must be the unbent ellipsoid's (4/3)π a b c, and its centroid at the origin.
  const CellKindConfig sickle = sickle_kind(CellBody::filled, MeshResolution::paper);
  const double spacing = 0.04;
  double count = 0;
  Vector3 moment{0, 0, 0};
  for (double x = -8.0 + spacing / 2; x < 8.0; x += spacing)
    for (double y = -6.0 + spacing / 2; y < 6.0; y += spacing)
      for (double z = -1.6 + spacing / 2; z < 1.6; z += spacing)
        if (inside_cell(sickle, {x, y, z})) {
          count += 1;
          moment[0] += x, moment[1] += y, moment[2] += z;
        }
  const double volume = count * spacing * spacing * spacing;
  const double ellipsoid_volume = 4.0 / 3.0 * pi * 7.0 * 2.1 * 1.5;
  std::cout << "  sickle volume by grid counting " << volume << " μm³ (ellipsoid " << ellipsoid_volume
            << "), centroid [" << moment[0] / count << ", " << moment[1] / count << ", " << moment[2] / count << "]\n";
  EXPECT_NEAR(volume, ellipsoid_volume, 0.003 * ellipsoid_volume);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(moment[d] / count, 0.0, 0.01);

  // The bend map and its inverse.
  const auto bend = geometry_detail::sickle_bend(sickle);
  for (const Vector3 p : {Vector3{0.0, 0.0, 0.0}, Vector3{6.5, -1.9, 0.4}, Vector3{-3.0, 2.0, -1.0}}) {
    const auto back = geometry_detail::unbend_sickle_point(bend, geometry_detail::bend_sickle_point(bend, p));
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(back[d], p[d], 1e-12);
  }
  // Its arc radius must exceed half the width.
  CellKindConfig folded = sickle;
  folded.arc_radius = 2.0;
  EXPECT_THROW(exact_cell_volume(folded), std::runtime_error);
  EXPECT_THROW(make_cell_mesh(folded), std::runtime_error);
}

TEST(CellShapes, SurfaceSamplesLieOnTheSurface) {
  const auto rbc = rbc_kind(CellBody::shell, MeshResolution::paper);
  const auto sphere = sphere_kind(CellBody::shell, MeshResolution::paper);
  const auto sickle = sickle_kind(CellBody::shell, MeshResolution::paper);
  const auto profile = exact_rbc_profile(3.91, 8192);
  const auto bend = geometry_detail::sickle_bend(sickle);
  const auto oblate = spheroid_kind(CellBody::filled, MeshResolution::paper, 1.0 / 3.0);
  const auto prolate = spheroid_kind(CellBody::filled, MeshResolution::paper, 2.0);
  for (const auto& kind : {rbc, sphere, sickle, oblate, prolate}) {
    const auto samples = cell_surface_samples(kind, 0.15);
    double worst = 0.0;  // distance from the surface (sickle, spheroid: |level| of the ellipsoid)
    for (const auto& p : samples) {
      if (kind.shape == CellShape::spheroid) worst = std::max(worst, std::abs(spheroid_level(kind, p)));
      if (kind.shape == CellShape::rbc) worst = std::max(worst, distance_to_polyline(profile, std::hypot(p[0], p[1]), p[2]));
      if (kind.shape == CellShape::sphere) worst = std::max(worst, std::abs(norm(p) - 2.82));
      if (kind.shape == CellShape::sickle) {
        const auto q = geometry_detail::unbend_sickle_point(bend, p);
        worst = std::max(worst, std::abs(q[0] * q[0] / 49.0 + q[1] * q[1] / 4.41 + q[2] * q[2] / 2.25 - 1.0));
      }
    }
    // Spacing: the area per sample is about spacing²; and no gap wider than about the
    // spacing: every point of a fine reference sampling has a sample within 0.15 μm.
    const double area_per_sample = exact_cell_area(kind) / samples.size();
    const auto reference = cell_surface_samples(kind, 0.05);
    double largest_gap = 0.0;
    for (std::size_t k = 0; k < reference.size(); k += 7) {
      double nearest = INFINITY;
      for (const auto& p : samples) nearest = std::min(nearest, norm(minus(p, reference[k])));
      largest_gap = std::max(largest_gap, nearest);
    }
    std::cout << "  " << kind.name << ": " << samples.size() << " samples, " << area_per_sample
              << " μm² each, off the surface by ≤ " << worst << ", farthest surface point from a sample "
              << largest_gap << " μm\n";
    EXPECT_LT(worst, 1e-6);
    EXPECT_GT(area_per_sample, 0.3 * 0.15 * 0.15);
    EXPECT_LT(area_per_sample, 1.5 * 0.15 * 0.15);
    EXPECT_LT(largest_gap, 0.15);
  }
}

TEST(CellShapes, RbcShellOffsetChecks) {
  // h = 0.36 leaves a cavity of 0.81 − 0.72 = 0.09 μm on the axis.
  CellKindConfig shell = rbc_kind(CellBody::shell, MeshResolution::paper);
  const auto inner = geometry_detail::rbc_inner_profile(shell, 400);
  EXPECT_NEAR(inner.front()[1] - inner.back()[1], 0.81 - 0.72, 0.01);
  // Thicker than half the centre thickness: no cavity left.
  shell.shell_thickness = 0.41;
  try {
    exact_cell_volume(shell);
    FAIL() << "no error for a shell thicker than half the centre thickness";
  } catch (const std::runtime_error& error) {
    std::cout << "  " << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("\"normal\""), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("no cavity"), std::string::npos);
  }
  shell.shell_thickness = 1.5;
  EXPECT_THROW(make_cell_mesh(shell), std::runtime_error);
  shell.shell_thickness = -0.1;
  EXPECT_THROW(make_cell_mesh(shell), std::runtime_error);
}

// ---- meshes

TEST(CellMesh, RbcFilledAndShellMatchTheExactShape) {
  // Straight-edged elements with their nodes on the curved surface cut inside it: the
  // enclosed volume and the area come out low by O(h²). The bounds below are those of
  // the presets (measured −4.8 % / −2.6 % coarse, −1.2 % / −0.7 % paper); the test
  // RbcMeshesConvergeToTheExactIntegrals shows the error is that faceting and nothing else.
  const double exact_volume = exact_cell_volume(rbc_kind(CellBody::filled, MeshResolution::paper));
  const double radius = 3.91;
  for (const auto resolution : {MeshResolution::coarse, MeshResolution::paper})
    for (const auto body : {CellBody::filled, CellBody::shell}) {
      const CellKindConfig kind = rbc_kind(body, resolution);
      const MeshedCell cell = mesh_and_report(kind);
      const bool coarse = resolution == MeshResolution::coarse;
      EXPECT_LT(cell.volume_error, 0.0);  // the facets cut inside a mostly convex surface
      EXPECT_GT(cell.volume_error, coarse ? -0.06 : -0.015);
      EXPECT_LT(std::abs(cell.area_error), coarse ? 0.035 : 0.01);
      // The nodes of the outer surface are on the exact surface (the spline through the
      // profile is within ~1e-5 μm of it).
      const double off_outer = largest_distance_from_profile(cell.mesh, cell.mesh.outer_surface, exact_rbc_profile(radius, 8192));
      EXPECT_LT(off_outer, 2e-4) << "outer surface nodes off the Evans–Fung surface";
      if (body == CellBody::shell) {
        const auto inner_profile = geometry_detail::rbc_inner_profile(kind, 8192);
        const double off_inner = largest_distance_from_profile(cell.mesh, cell.mesh.inner_surface, inner_profile);
        EXPECT_LT(off_inner, 2e-4) << "cavity wall nodes off the offset surface";
        const double exact_solid = exact_volume - revolved_volume(inner_profile);
        const double solid_error = (cell.report.solid_volume - exact_solid) / exact_solid;
        std::cout << "    shell solid volume " << cell.report.solid_volume << " μm³ (exact " << exact_solid << ", "
                  << 100 * solid_error << " %), nodes off the surfaces by ≤ " << std::max(off_outer, off_inner) << " μm\n";
        EXPECT_LT(std::abs(solid_error), coarse ? 0.05 : 0.02);
      }
      // The body frame: centroid at the origin (to the mesh's asymmetry), axis along z.
      const Vector3 centroid = enclosed_centroid(cell.mesh, cell.mesh.outer_surface);
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(centroid[d], 0.0, coarse ? 0.01 : 0.003);
    }
}

TEST(CellMesh, RbcMeshesConvergeToTheExactIntegrals) {
  // The faceting error is c h²: meshes at h and h/√2 extrapolate (Richardson,
  // 2 V(h/√2) − V(h)) to within a small fraction of it.
  CellKindConfig kind = rbc_kind(CellBody::filled, MeshResolution::paper);
  const double exact_volume = exact_cell_volume(kind), exact_area = exact_cell_area(kind);
  kind.mesh_size = 0.5;
  const MeshedCell first = mesh_and_report(kind);
  kind.mesh_size = 0.5 / std::sqrt(2.0);
  const MeshedCell second = mesh_and_report(kind);
  const double volume = 2 * second.report.enclosed_volume - first.report.enclosed_volume;
  const double area = 2 * second.report.outer_area - first.report.outer_area;
  std::cout << "  Richardson: V = " << volume << " (" << 100 * (volume - exact_volume) / exact_volume << " %), A = " << area
            << " (" << 100 * (area - exact_area) / exact_area << " %)\n";
  EXPECT_LT(std::abs(second.volume_error), 0.7 * std::abs(first.volume_error));
  // At h = 0.35 μm (about 2400 nodes, filled) the meshed RBC is within 1 %
  // of the exact volume and area.
  std::cout << "  h = " << kind.mesh_size << " μm: " << second.mesh.nodes.size() << " nodes, volume "
            << 100 * second.volume_error << " %, area " << 100 * second.area_error << " %\n";
  EXPECT_LT(std::abs(second.volume_error), 0.01);
  EXPECT_LT(std::abs(second.area_error), 0.01);
  EXPECT_NEAR(volume, exact_volume, 0.002 * exact_volume);
  EXPECT_NEAR(area, exact_area, 0.002 * exact_area);
}

TEST(CellMesh, SphereFilledAndShell) {
  for (const auto body : {CellBody::filled, CellBody::shell}) {
    const CellKindConfig kind = sphere_kind(body, MeshResolution::paper);
    const MeshedCell cell = mesh_and_report(kind);
    const double radius = 0.5 * kind.diameter;
    EXPECT_NEAR(exact_cell_volume(kind), 4.0 / 3.0 * pi * radius * radius * radius, 1e-12);
    // Measured −1.1 % / −0.6 % (faceting, as for the RBC).
    EXPECT_LT(std::abs(cell.volume_error), 0.015);
    EXPECT_LT(std::abs(cell.area_error), 0.01);
    std::set<int> outer_nodes;
    for (const auto& f : cell.mesh.outer_surface) outer_nodes.insert(f.begin(), f.end());
    for (int i : outer_nodes) ASSERT_NEAR(norm(cell.mesh.nodes[i]), radius, 1e-6);
    if (body == CellBody::shell) {
      const double inner = radius - kind.shell_thickness;
      const double exact_solid = 4.0 / 3.0 * pi * (radius * radius * radius - inner * inner * inner);
      std::cout << "    shell solid volume " << cell.report.solid_volume << " μm³ (exact " << exact_solid << ", "
                << 100 * (cell.report.solid_volume - exact_solid) / exact_solid << " %)\n";
      EXPECT_NEAR(cell.report.solid_volume, exact_solid, 0.02 * exact_solid);
      std::set<int> inner_nodes;
      for (const auto& f : cell.mesh.inner_surface) inner_nodes.insert(f.begin(), f.end());
      for (int i : inner_nodes) ASSERT_NEAR(norm(cell.mesh.nodes[i]), inner, 1e-6);
    }
  }
  // The coarse preset for CI: a few hundred nodes.
  const MeshedCell coarse = mesh_and_report(sphere_kind(CellBody::shell, MeshResolution::coarse));
  EXPECT_LT(coarse.mesh.nodes.size(), 600u);
  EXPECT_LT(std::abs(coarse.volume_error), 0.06);
}

TEST(CellMesh, SpheroidFilled) {
  // An oblate (c/a = 1/3, the red cell's diameter and about its thickness) and two prolate
  // spheroids (c/a = 2, and a rod 3 μm thick and 9 μm long: with the unit sphere's poles
  // on its flat side Gmsh made no volume elements of it) at each preset: the outer nodes
  // on the exact surface, the volume and area within the faceting errors of the sphere
  // and the RBC (measured at the paper's preset: −0.87 % and −0.42 % oblate, −1.2 % and
  // −0.64 % prolate).
  for (const auto& [diameter, ratio] : std::vector<std::pair<double, double>>{{7.82, 1.0 / 3.0}, {7.82, 2.0}, {3.0, 3.0}})
    for (const auto resolution : {MeshResolution::coarse, MeshResolution::paper}) {
      CellKindConfig kind = spheroid_kind(CellBody::filled, resolution, ratio);
      kind.diameter = diameter;
      const MeshedCell cell = mesh_and_report(kind);
      const bool coarse = resolution == MeshResolution::coarse;
      EXPECT_LT(cell.volume_error, 0.0);  // the facets cut inside a convex surface
      EXPECT_GT(cell.volume_error, coarse ? -0.06 : -0.015);
      EXPECT_LT(std::abs(cell.area_error), coarse ? 0.035 : 0.01);
      std::set<int> outer_nodes;
      for (const auto& f : cell.mesh.outer_surface) outer_nodes.insert(f.begin(), f.end());
      for (int i : outer_nodes) ASSERT_NEAR(spheroid_level(kind, cell.mesh.nodes[i]), 0.0, 1e-6);
    }
  // A spheroid shell is refused: Gmsh meshes the layer between two scaled spheres with
  // slivers (smallest quality 0.01–0.05 at element sizes 0.3–0.9 μm, against 0.04 required).
  const CellKindConfig shell = spheroid_kind(CellBody::shell, MeshResolution::paper, 1.0 / 3.0);
  EXPECT_THROW(exact_cell_volume(shell), std::runtime_error);
}

TEST(CellMesh, SickleFilledAndShell) {
  const double ellipsoid_volume = 4.0 / 3.0 * pi * 7.0 * 2.1 * 1.5;
  for (const auto resolution : {MeshResolution::coarse, MeshResolution::paper})
    for (const auto body : {CellBody::filled, CellBody::shell}) {
      const CellKindConfig kind = sickle_kind(body, resolution);
      const MeshedCell cell = mesh_and_report(kind);
      const bool coarse = resolution == MeshResolution::coarse;
      const double volume_error = (cell.report.enclosed_volume - ellipsoid_volume) / ellipsoid_volume;
      // Measured −3.9 % / −1.4 % coarse, −1.2 % / −0.5 % paper (faceting).
      EXPECT_LT(std::abs(volume_error), coarse ? 0.05 : 0.015);
      EXPECT_LT(std::abs(cell.area_error), coarse ? 0.025 : 0.01);
      // Surface nodes on the bent ellipsoid: unbent, they satisfy (x/a)² + (y/b)² + (z/c)² = 1.
      const auto bend = geometry_detail::sickle_bend(kind);
      std::set<int> outer_nodes;
      for (const auto& f : cell.mesh.outer_surface) outer_nodes.insert(f.begin(), f.end());
      double worst = 0.0;
      for (int i : outer_nodes) {
        const auto q = geometry_detail::unbend_sickle_point(bend, cell.mesh.nodes[i]);
        worst = std::max(worst, std::abs(q[0] * q[0] / 49.0 + q[1] * q[1] / 4.41 + q[2] * q[2] / 2.25 - 1.0));
      }
      EXPECT_LT(worst, 1e-5) << "outer nodes off the bent ellipsoid";
      // Centroid of the enclosed volume at the origin (to the faceting error).
      const Vector3 centroid = enclosed_centroid(cell.mesh, cell.mesh.outer_surface);
      std::cout << "    enclosed-volume centroid [" << centroid[0] << ", " << centroid[1] << ", " << centroid[2]
                << "], nodes off the surface (level) ≤ " << worst << "\n";
      EXPECT_NEAR(centroid[0], 0.0, coarse ? 0.01 : 0.003);
      EXPECT_NEAR(centroid[1], 0.0, coarse ? 0.03 : 0.01);
      EXPECT_NEAR(centroid[2], 0.0, coarse ? 0.01 : 0.003);
    }
}

TEST(CellMesh, IsDeterministicAndCoversEveryPreset) {
  const CellKindConfig kind = rbc_kind(CellBody::shell, MeshResolution::coarse);
  const CellMesh first = make_cell_mesh(kind), second = make_cell_mesh(kind);
  EXPECT_EQ(first.nodes, second.nodes);
  EXPECT_EQ(first.tetrahedra, second.tetrahedra);
  EXPECT_EQ(first.outer_surface, second.outer_surface);
  EXPECT_EQ(first.inner_surface, second.inner_surface);
  EXPECT_EQ(first.hash, second.hash);
  // Presets: fine is half the paper size, coarse twice; mesh_size overrides; sizes scale
  // with the cube root of the volume.
  CellKindConfig paper = rbc_kind(CellBody::shell, MeshResolution::paper);
  CellKindConfig fine = rbc_kind(CellBody::shell, MeshResolution::fine);
  EXPECT_NEAR(cell_element_size(fine), 0.5 * cell_element_size(paper), 1e-12);
  EXPECT_NEAR(cell_element_size(kind), 2.0 * cell_element_size(paper), 1e-12);
  paper.mesh_size = 0.3;
  EXPECT_DOUBLE_EQ(cell_element_size(paper), 0.3);
  CellKindConfig larger = rbc_kind(CellBody::shell, MeshResolution::paper);
  larger.diameter = 2 * 7.82;
  EXPECT_NEAR(cell_element_size(larger), 2.0 * cell_element_size(rbc_kind(CellBody::shell, MeshResolution::paper)), 1e-9);
}

// ---- cache

TEST(CellMeshCache, StoresReadsAndRemakes) {
  TemporaryDirectory directory("cellmesh-cache");
  const std::string cache = (directory.path() / "meshes").string();  // made on demand
  const CellKindConfig kind = rbc_kind(CellBody::shell, MeshResolution::coarse);

  auto start = std::chrono::steady_clock::now();
  const CellMesh made = cell_mesh(kind, cache);
  const double make_time = seconds_since(start);
  const fs::path file = fs::path(cache) / ("cellmesh-" + made.hash + ".txt");
  ASSERT_TRUE(fs::exists(file));
  // No temporary left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(cache), fs::directory_iterator()), 1);
  {
    std::ifstream in(file);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "rouleau-cell-mesh 1");
  }

  // Read back: the same mesh, the file untouched.
  const auto old_time = fs::last_write_time(file) - std::chrono::hours(1);
  fs::last_write_time(file, old_time);
  start = std::chrono::steady_clock::now();
  const CellMesh read = cell_mesh(kind, cache);
  const double read_time = seconds_since(start);
  std::cout << "  made in " << make_time << " s, read from the cache in " << read_time << " s\n";
  EXPECT_EQ(fs::last_write_time(file), old_time) << "the cached mesh was made again";
  EXPECT_EQ(read.nodes, made.nodes);
  EXPECT_EQ(read.tetrahedra, made.tetrahedra);
  EXPECT_EQ(read.outer_surface, made.outer_surface);
  EXPECT_EQ(read.inner_surface, made.inner_surface);
  EXPECT_EQ(read.hash, made.hash);

  // Damaged files are remade: truncated, an index out of range, a coordinate not finite.
  std::string text;
  {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const auto damage = [&](const std::string& what, const std::string& damaged) {
    { std::ofstream(file, std::ios::trunc) << damaged; }
    fs::last_write_time(file, old_time);
    const CellMesh remade = cell_mesh(kind, cache);
    EXPECT_NE(fs::last_write_time(file), old_time) << what << ": not remade";
    EXPECT_EQ(remade.nodes, made.nodes) << what;
    EXPECT_EQ(remade.tetrahedra, made.tetrahedra) << what;
    std::ifstream in(file);
    const std::string rewritten((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(rewritten, text) << what << ": the remade file differs";
  };
  damage("truncated", text.substr(0, text.size() / 2));
  damage("empty", "");
  {
    std::string bad = text;
    const auto at = bad.find("tetrahedra ");
    const auto line = bad.find('\n', at) + 1;
    bad.replace(line, bad.find(' ', line) - line, "999999");
    damage("index out of range", bad);
  }
  {
    std::string bad = text;
    const auto at = bad.find("nodes ");
    const auto line = bad.find('\n', at) + 1;
    bad.replace(line, bad.find(' ', line) - line, "nan");
    damage("not finite", bad);
  }
  {
    std::string bad = text;
    bad.replace(bad.find("hash ") + 5, 16, "0123456789abcdef");
    damage("wrong hash inside", bad);
  }
}

TEST(CellMeshCache, HashesEveryParameterThatChangesTheMesh) {
  const CellKindConfig base = rbc_kind(CellBody::shell, MeshResolution::coarse);
  TemporaryDirectory directory("cellmesh-hash");
  const std::string hash = cell_mesh(base, directory.path().string()).hash;
  std::set<std::string> hashes{hash};
  std::vector<CellKindConfig> changed;
  changed.push_back(base), changed.back().diameter = 7.83;
  changed.push_back(base), changed.back().body = CellBody::filled;
  changed.push_back(base), changed.back().shell_thickness = 0.3;
  changed.push_back(base), changed.back().resolution = MeshResolution::paper;
  changed.push_back(base), changed.back().mesh_size = 0.9;
  changed.push_back(sphere_kind(CellBody::shell, MeshResolution::coarse));
  changed.push_back(sickle_kind(CellBody::shell, MeshResolution::coarse));
  changed.push_back(spheroid_kind(CellBody::filled, MeshResolution::coarse, 1.0 / 3.0));
  changed.push_back(spheroid_kind(CellBody::filled, MeshResolution::coarse, 0.5));
  changed.push_back(sickle_kind(CellBody::shell, MeshResolution::coarse)), changed.back().arc_radius = 9.0;
  changed.push_back(sickle_kind(CellBody::shell, MeshResolution::coarse)), changed.back().thickness = 2.8;
  for (const auto& kind : changed) {
    // The hash is decided before any meshing; mesh only the cheap ones.
    const CellMesh mesh = cell_mesh(kind, directory.path().string());
    hashes.insert(mesh.hash);
  }
  EXPECT_EQ(hashes.size(), changed.size() + 1) << "two different kinds share a hash";
  // The material and the name do not enter: the same mesh, read from the cache.
  CellKindConfig material = base;
  material.name = "other";
  material.shear_modulus *= 10;
  material.density *= 2;
  EXPECT_EQ(cell_mesh(material, directory.path().string()).hash, hash);
  // A file of one kind renamed to another's hash is not taken for it.
  const CellKindConfig other = changed.front();
  const std::string other_hash = cell_mesh(other, directory.path().string()).hash;
  fs::copy_file(directory.path() / ("cellmesh-" + hash + ".txt"), directory.path() / ("cellmesh-" + other_hash + ".txt"),
                fs::copy_options::overwrite_existing);
  const CellMesh remade = cell_mesh(other, directory.path().string());
  EXPECT_EQ(remade.hash, other_hash);
  EXPECT_NE(remade.nodes, cell_mesh(base, directory.path().string()).nodes);
}

TEST(CellMeshCache, DefaultDirectoryFollowsTheEnvironment) {
  const auto saved = [](const char* name) {
    const char* value = std::getenv(name);
    return value ? std::optional<std::string>(value) : std::nullopt;
  };
  const auto cache = saved("ROULEAU_MESH_CACHE"), xdg = saved("XDG_CACHE_HOME"), home = saved("HOME");
  ::setenv("ROULEAU_MESH_CACHE", "/tmp/a", 1);
  ::setenv("XDG_CACHE_HOME", "/tmp/b", 1);
  ::setenv("HOME", "/tmp/c", 1);
  EXPECT_EQ(default_mesh_cache_dir(), "/tmp/a");
  ::unsetenv("ROULEAU_MESH_CACHE");
  EXPECT_EQ(default_mesh_cache_dir(), "/tmp/b/rouleau/meshes");
  ::unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(default_mesh_cache_dir(), "/tmp/c/.cache/rouleau/meshes");
  ::unsetenv("HOME");
  EXPECT_EQ(default_mesh_cache_dir(), "./.rouleau-mesh-cache");
  const auto restore = [](const char* name, const std::optional<std::string>& value) {
    if (value) ::setenv(name, value->c_str(), 1);
    else ::unsetenv(name);
  };
  restore("ROULEAU_MESH_CACHE", cache);
  restore("XDG_CACHE_HOME", xdg);
  restore("HOME", home);
}

// ---- placement

CaseConfig shear_box_case() {
  CaseConfig config;
  config.source_file = "placement.toml";
  config.domain.lower = {0.0, 0.0, 0.0};
  config.domain.upper = {40.0, 20.0, 20.0};
  config.cell_kinds = builtin_cell_kinds();
  return config;
}
CellPlacement placed(const std::string& kind, Vector3 center, Vector3 orientation = {0, 0, 0}) {
  CellPlacement cell;
  cell.kind = kind;
  cell.center = center;
  cell.orientation = orientation;
  return cell;
}
// The InputError check_cell_placement throws, or a test failure.
InputError placement_error(const CaseConfig& config) {
  try {
    check_cell_placement(config);
  } catch (const InputError& error) {
    std::cout << "  " << error.what() << "\n";
    return error;
  }
  ADD_FAILURE() << "check_cell_placement accepted the cells";
  return InputError("", "", "");
}

TEST(CellPlacement, RotationIsAboutFixedXThenYThenZ) {
  CellPlacement cell = placed("normal", {0, 0, 0}, {0, 0, 90});
  auto r = placement_rotation(cell.orientation);
  // e_x → e_y for 90° about z.
  EXPECT_NEAR(r[1][0], 1.0, 1e-12);
  // 90° about x, then 90° about y: e_y → e_z → e_x (the other order would give e_z).
  cell.orientation = {90, 90, 0};
  r = placement_rotation(cell.orientation);
  EXPECT_NEAR(r[0][1], 1.0, 1e-12);
  EXPECT_NEAR(r[1][1], 0.0, 1e-12);
  EXPECT_NEAR(r[2][1], 0.0, 1e-12);
}

TEST(CellPlacement, RouleauStackFits) {
  // Four normal RBCs face to face along z, 3.96 μm between centres (thickness 2.57 μm:
  // 1.39 μm between rims), in the paper's 40 × 20 × 20 μm box.
  CaseConfig config = shear_box_case();
  for (int i = 0; i < 4; ++i) config.cells.push_back(placed("normal", {20.0, 10.0, 10.0 + (i - 1.5) * 3.96}));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NO_THROW(check_cell_placement(config));
  std::cout << "  four-cell stack checked in " << seconds_since(start) << " s\n";
  // Spheres with a 0.3 μm gap pass; with 0.1 μm overlap they fail.
  CaseConfig spheres = shear_box_case();
  spheres.cells = {placed("capsule", {10, 10, 10}), placed("capsule", {10 + 5.64 + 0.3, 10, 10})};
  EXPECT_NO_THROW(check_cell_placement(spheres));
  spheres.cells[1].center[0] = 10 + 5.64 - 0.1;
  EXPECT_EQ(placement_error(spheres).key(), "cells[1].center_um");
  // Crescents nested into each other's bend (convex side toward +y): 4.5 μm apart along
  // y they clear each other (width 4.2 μm), 3 μm apart they overlap.
  CaseConfig sickles = shear_box_case();
  sickles.cells = {placed("sickle", {20, 7, 10}), placed("sickle", {20, 11.5, 10})};
  EXPECT_NO_THROW(check_cell_placement(sickles));
  sickles.cells[1].center[1] = 10.0;
  EXPECT_EQ(placement_error(sickles).key(), "cells[1].center_um");
}

TEST(CellPlacement, OverlapNamesBothCells) {
  CaseConfig config = shear_box_case();
  config.cells = {placed("normal", {10, 10, 10}), placed("sickle", {30, 10, 10}), placed("normal", {11, 10, 10})};
  const InputError error = placement_error(config);
  EXPECT_EQ(error.file(), "placement.toml");
  EXPECT_EQ(error.key(), "cells[2].center_um");
  EXPECT_NE(error.reason().find("cells[0]"), std::string::npos);
  EXPECT_NE(error.reason().find("normal at [10, 10, 10]"), std::string::npos);
  EXPECT_NE(error.reason().find("overlaps"), std::string::npos);
}

TEST(CellPlacement, CellOutsideTheDomainNamesTheAxis) {
  CaseConfig config = shear_box_case();
  config.cells = {placed("normal", {20, 10, 10}), placed("normal", {20, 3.5, 10})};  // radius 3.91 along y
  const InputError error = placement_error(config);
  EXPECT_EQ(error.key(), "cells[1].center_um");
  EXPECT_NE(error.reason().find("outside the fluid domain"), std::string::npos);
  EXPECT_NE(error.reason().find("along y"), std::string::npos);

  // Near the z = 0 wall a flat cell fits (half-thickness 1.29 μm) ...
  config.cells = {placed("normal", {20, 10, 2.5})};
  EXPECT_NO_THROW(check_cell_placement(config));
  // ... but turned 90° about x its 3.91 μm radius reaches through the wall.
  config.cells[0].orientation = {90, 0, 0};
  const InputError turned = placement_error(config);
  EXPECT_EQ(turned.key(), "cells[0].center_um");
  EXPECT_NE(turned.reason().find("along z"), std::string::npos);
}

TEST(CellPlacement, UnknownKindAndBadKind) {
  CaseConfig config = shear_box_case();
  config.cells = {placed("normal", {20, 10, 10}), placed("ghost", {30, 10, 10})};
  const InputError error = placement_error(config);
  EXPECT_EQ(error.key(), "cells[1].kind");
  EXPECT_NE(error.reason().find("unknown cell kind \"ghost\""), std::string::npos);
  EXPECT_NE(error.reason().find("\"normal\", \"sickle\", \"capsule\""), std::string::npos);

  // A kind whose sizes make no body is reported against the kind.
  config.cells.pop_back();
  for (auto& kind : config.cell_kinds)
    if (kind.name == "normal") kind.shell_thickness = 0.5;
  const InputError bad = placement_error(config);
  EXPECT_EQ(bad.key(), "cell_kinds.normal");
}

TEST(CellPlacement, AHugeCellIsRejectedBeforeItIsSampled) {
  // A diameter of 6782 μm (a fuzzer's find) would have needed 6.4e9 surface samples for the
  // placement check and exhausted the memory: it is refused against the kind, at once.
  CaseConfig config = shear_box_case();
  config.cells = {placed("normal", {20, 10, 10})};
  for (auto& kind : config.cell_kinds)
    if (kind.name == "normal") kind.diameter = 6782.0;
  const InputError error = placement_error(config);
  EXPECT_EQ(error.key(), "cell_kinds.normal");
  EXPECT_NE(error.reason().find("the cell is too large"), std::string::npos);
}

}  // namespace
