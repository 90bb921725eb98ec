#include "geometry/tetrahedral_mesh.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

namespace rouleau {

namespace {
// A triangle turned (cyclically, keeping its orientation) to start at its smallest index.
Triangle starting_at_smallest(const Triangle& f) {
  if (f[1] < f[0] && f[1] < f[2]) return {f[1], f[2], f[0]};
  if (f[2] < f[0] && f[2] < f[1]) return {f[2], f[0], f[1]};
  return f;
}

}  // namespace

TetrahedralMesh gmsh_tetrahedra() {
  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(node_tags, coordinates, parametric);
  std::vector<std::size_t> element_tags, element_nodes;
  const int linear_tetrahedron = 4;  // Gmsh element type
  gmsh::model::mesh::getElementsByType(linear_tetrahedron, element_tags, element_nodes);

  // Keep the nodes the tetrahedra use, numbered in Gmsh's tag order.
  const std::size_t largest_tag = node_tags.empty() ? 0 : *std::max_element(node_tags.begin(), node_tags.end());
  std::vector<long> index_of_tag(largest_tag + 1, -1);
  std::vector<std::size_t> position_of_tag(largest_tag + 1, 0);
  std::vector<char> known(largest_tag + 1, 0), used(largest_tag + 1, 0);
  for (std::size_t i = 0; i < node_tags.size(); ++i) position_of_tag[node_tags[i]] = i, known[node_tags[i]] = 1;
  for (std::size_t tag : element_nodes) {
    if (tag > largest_tag || !known[tag]) throw std::runtime_error("Gmsh returned a tetrahedron with an unknown node");
    used[tag] = 1;
  }
  TetrahedralMesh mesh;
  for (std::size_t tag = 0; tag <= largest_tag; ++tag) {
    if (!used[tag]) continue;
    index_of_tag[tag] = static_cast<long>(mesh.nodes.size());
    const std::size_t i = position_of_tag[tag];
    mesh.nodes.push_back({coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]});
  }
  mesh.tetrahedra.resize(element_tags.size());
  for (std::size_t e = 0; e < element_tags.size(); ++e)
    for (int v = 0; v < 4; ++v) mesh.tetrahedra[e][v] = static_cast<int>(index_of_tag[element_nodes[4 * e + v]]);
  return mesh;
}

TetrahedralMesh mesh_volumes(double largest_size, const std::function<double(double, double, double)>& size) {
  gmsh::option::setNumber("Mesh.MeshSizeMax", largest_size);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::model::mesh::setSizeCallback([&size](int, int, double x, double y, double z) { return size(x, y, z); });
  struct RemoveSizeCallback {  // before `size` goes, whatever happens
    ~RemoveSizeCallback() {
      try {
        gmsh::model::mesh::removeSizeCallback();
      } catch (...) {
      }
    }
  } remove_size_callback;
  gmsh::option::setNumber("Mesh.Algorithm", 6);    // Frontal-Delaunay surfaces
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);  // Delaunay volumes: the same mesh every run
  gmsh::option::setNumber("Mesh.Optimize", 1);
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::model::mesh::generate(3);
  return gmsh_tetrahedra();
}

double signed_volume6(const MeshPoint& x0, const MeshPoint& x1, const MeshPoint& x2, const MeshPoint& x3) {
  // 6 V = (x1 − x0) · ((x2 − x0) × (x3 − x0))
  const double a[3] = {x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]};
  const double b[3] = {x2[0] - x0[0], x2[1] - x0[1], x2[2] - x0[2]};
  const double c[3] = {x3[0] - x0[0], x3[1] - x0[1], x3[2] - x0[2]};
  return a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

double tetrahedron_quality(const std::vector<MeshPoint>& nodes, const Tetrahedron& t) {
  double longest_squared = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      double squared = 0.0;
      for (int d = 0; d < 3; ++d) squared += (nodes[t[i]][d] - nodes[t[j]][d]) * (nodes[t[i]][d] - nodes[t[j]][d]);
      longest_squared = std::max(longest_squared, squared);
    }
  const double volume6 = signed_volume6(nodes[t[0]], nodes[t[1]], nodes[t[2]], nodes[t[3]]);
  return std::sqrt(2.0) * volume6 / (longest_squared * std::sqrt(longest_squared));
}

OrientationReport orient_tetrahedra(const std::vector<MeshPoint>& nodes, std::vector<Tetrahedron>& tetrahedra) {
  std::size_t negative = 0;
  for (const auto& t : tetrahedra)
    if (signed_volume6(nodes[t[0]], nodes[t[1]], nodes[t[2]], nodes[t[3]]) < 0.0) ++negative;
  const bool flip = 2 * negative > tetrahedra.size();
  OrientationReport report;
  report.worst_quality = INFINITY;
  for (auto& t : tetrahedra) {
    if (flip) std::swap(t[2], t[3]);
    const double quality = tetrahedron_quality(nodes, t);
    report.worst_quality = std::min(report.worst_quality, quality);
    if (quality < 0.0) ++report.inverted;
    else if (!(quality >= degenerate_quality)) ++report.degenerate;
  }
  return report;
}

void require_valid_orientation(const OrientationReport& report, const std::string& what) {
  if (report.inverted == 0 && report.degenerate == 0) return;
  throw std::runtime_error(what + ": the mesh has " + std::to_string(report.inverted) + " inverted and " +
                           std::to_string(report.degenerate) + " degenerate tetrahedra (worst quality 6√2V/l³ = " +
                           std::to_string(report.worst_quality) + ")");
}

void canonicalize_tetrahedra(std::vector<Tetrahedron>& tetrahedra) {
  for (auto& t : tetrahedra) {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += t[i] > t[j];
    std::sort(t.begin(), t.end());
    if (inversions % 2 == 1) std::swap(t[2], t[3]);
  }
  std::sort(tetrahedra.begin(), tetrahedra.end());
}

// Boundary slivers. Gmsh's Delaunay mesher sometimes leaves a flat tetrahedron on the
// surface with two of its faces there (on a slightly curved patch, above the boundary
// edge they share; mostly at the poles of the revolved and spherical surfaces). Removing
// it swaps that boundary edge for the opposite one, an edge flip of the surface
// triangulation whose four nodes all stay on the exact surface; the volume changes by
// the sliver's (tiny) volume. Done when the opposite edge is not already a boundary edge
// (the surface stays manifold), one sliver per node per pass. Returns how many.
constexpr double sliver_quality = 0.1;
std::size_t peel_boundary_slivers(const std::vector<MeshPoint>& nodes, std::vector<Tetrahedron>& tetrahedra) {
  static constexpr int faces_of[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  const auto sorted_face = [](int a, int b, int c) {
    Triangle f{a, b, c};
    std::sort(f.begin(), f.end());
    return f;
  };
  std::size_t peeled = 0;
  for (int pass = 0; pass < 10; ++pass) {
    std::vector<Triangle> all_faces;
    all_faces.reserve(4 * tetrahedra.size());
    for (const auto& t : tetrahedra)
      for (const auto& f : faces_of) all_faces.push_back(sorted_face(t[f[0]], t[f[1]], t[f[2]]));
    std::sort(all_faces.begin(), all_faces.end());
    std::vector<Triangle> boundary;
    std::vector<std::pair<int, int>> boundary_edges;
    for (std::size_t i = 0; i < all_faces.size();) {
      std::size_t j = i + 1;
      while (j < all_faces.size() && all_faces[j] == all_faces[i]) ++j;
      if (j - i == 1) {
        const Triangle& f = all_faces[i];
        boundary.push_back(f);
        boundary_edges.insert(boundary_edges.end(), {{f[0], f[1]}, {f[0], f[2]}, {f[1], f[2]}});
      }
      i = j;
    }
    std::sort(boundary_edges.begin(), boundary_edges.end());
    const auto on_boundary = [&](const Triangle& f) { return std::binary_search(boundary.begin(), boundary.end(), f); };
    std::vector<char> remove(tetrahedra.size(), 0), touched(nodes.size(), 0);
    std::size_t removed_this_pass = 0;
    for (std::size_t e = 0; e < tetrahedra.size(); ++e) {
      const auto& t = tetrahedra[e];
      if (touched[t[0]] || touched[t[1]] || touched[t[2]] || touched[t[3]]) continue;
      if (tetrahedron_quality(nodes, t) >= sliver_quality) continue;
      int boundary_faces = 0;
      std::array<int, 4> uses{0, 0, 0, 0};  // how many boundary faces each corner is on
      for (const auto& f : faces_of)
        if (on_boundary(sorted_face(t[f[0]], t[f[1]], t[f[2]]))) {
          ++boundary_faces;
          for (int k : f) ++uses[k];
        }
      if (boundary_faces != 2) continue;
      // The corners on one boundary face only span the edge that becomes a boundary edge.
      std::array<int, 2> opposite{-1, -1};
      int found = 0;
      for (int k = 0; k < 4; ++k)
        if (uses[k] == 1 && found < 2) opposite[found++] = t[k];
      if (found != 2) continue;
      const std::pair<int, int> new_edge{std::min(opposite[0], opposite[1]), std::max(opposite[0], opposite[1])};
      if (std::binary_search(boundary_edges.begin(), boundary_edges.end(), new_edge)) continue;
      remove[e] = 1;
      for (int v : t) touched[v] = 1;
      ++removed_this_pass;
    }
    if (removed_this_pass == 0) break;
    std::size_t kept = 0;
    for (std::size_t e = 0; e < tetrahedra.size(); ++e)
      if (!remove[e]) tetrahedra[kept++] = tetrahedra[e];
    tetrahedra.resize(kept);
    peeled += removed_this_pass;
  }
  return peeled;
}

void drop_unused_nodes(std::vector<MeshPoint>& nodes, std::vector<Tetrahedron>& tetrahedra) {
  std::vector<int> new_index(nodes.size(), -1);
  for (const auto& t : tetrahedra)
    for (int v : t) new_index[v] = 0;
  int count = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (new_index[i] == 0) {
      new_index[i] = count;
      nodes[count++] = nodes[i];
    }
  nodes.resize(count);
  for (auto& t : tetrahedra)
    for (int& v : t) v = new_index[v];
}

void renumber_nodes_for_locality(std::vector<MeshPoint>& nodes, std::vector<Tetrahedron>& tetrahedra) {
  const int count = static_cast<int>(nodes.size());
  // The edge graph in CSR form, neighbours sorted.
  std::vector<std::vector<int>> neighbors(count);
  for (const auto& t : tetrahedra)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        if (i != j) neighbors[t[i]].push_back(t[j]);
  for (auto& list : neighbors) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  // Breadth-first order from `start` over the unvisited nodes, neighbours by increasing
  // degree; returns the last level's first node (a far node) through `far`.
  std::vector<int> order, level(count, -1);
  const auto breadth_first = [&](int start, std::vector<int>& visit, int& far) {
    std::fill(level.begin(), level.end(), -1);
    visit.clear();
    visit.push_back(start);
    level[start] = 0;
    for (std::size_t k = 0; k < visit.size(); ++k) {
      std::vector<int> next;
      for (int m : neighbors[visit[k]])
        if (level[m] < 0) next.push_back(m);
      std::stable_sort(next.begin(), next.end(),
                       [&](int a, int b) { return neighbors[a].size() < neighbors[b].size(); });
      for (int m : next) {
        level[m] = level[visit[k]] + 1;
        visit.push_back(m);
      }
    }
    far = visit.back();
    for (int m : visit)
      if (level[m] == level[visit.back()] && neighbors[m].size() < neighbors[far].size()) far = m;
  };
  std::vector<char> placed(count, 0);
  std::vector<int> visit;
  for (int seed = 0; seed < count; ++seed) {
    if (placed[seed]) continue;
    // A pseudo-peripheral start: the far end of two sweeps from the component's first node.
    int far = seed;
    for (int sweep = 0; sweep < 2; ++sweep) breadth_first(far, visit, far);
    breadth_first(far, visit, far);
    for (int m : visit) placed[m] = 1;
    order.insert(order.end(), visit.begin(), visit.end());
  }
  std::reverse(order.begin(), order.end());
  std::vector<int> new_index(count);
  std::vector<MeshPoint> renumbered(count);
  for (int k = 0; k < count; ++k) {
    new_index[order[k]] = k;
    renumbered[k] = nodes[order[k]];
  }
  nodes = std::move(renumbered);
  for (auto& t : tetrahedra)
    for (int& v : t) v = new_index[v];
}

// For a positive tetrahedron (0, 1, 2, 3) the faces seen from outside, counter-clockwise,
// are (0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2). A face of one tetrahedron only is on the
// boundary.
std::vector<Triangle> boundary_triangles(const std::vector<Tetrahedron>& tetrahedra) {
  static constexpr int face_corners[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  struct Face {
    Triangle sorted, oriented;
  };
  std::vector<Face> faces;
  faces.reserve(4 * tetrahedra.size());
  for (const auto& t : tetrahedra)
    for (const auto& corners : face_corners) {
      Face face;
      face.oriented = {t[corners[0]], t[corners[1]], t[corners[2]]};
      face.sorted = face.oriented;
      std::sort(face.sorted.begin(), face.sorted.end());
      faces.push_back(face);
    }
  std::sort(faces.begin(), faces.end(), [](const Face& l, const Face& r) {
    return l.sorted < r.sorted || (l.sorted == r.sorted && l.oriented < r.oriented);
  });
  std::vector<Triangle> boundary;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].sorted == faces[i].sorted) ++j;
    if (j - i == 1) boundary.push_back(starting_at_smallest(faces[i].oriented));
    else if (j - i > 2)
      throw std::runtime_error("a face of the mesh is shared by " + std::to_string(j - i) + " tetrahedra");
    i = j;
  }
  return boundary;
}

// FNV-1a, 64 bits: h ← (h XOR byte) × 1099511628211 from h = 14695981039346656037.
std::string fnv1a_hex(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char byte : text) {
    hash ^= byte;
    hash *= 1099511628211ull;
  }
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016" PRIx64, hash);
  return digits;
}

}  // namespace rouleau
