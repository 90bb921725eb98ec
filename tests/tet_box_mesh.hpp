#pragma once
// A box of 4-node tetrahedra (each hexahedral cell split into six along its main
// diagonal, Freudenthal/Kuhn) with its outer surface: a mesh with exactly known volume,
// area and centroid for the solid-kernel tests, independent of Gmsh.
#include <algorithm>
#include <array>
#include <map>

#include "geometry/cell_mesh.hpp"

namespace rouleau::testing {

// A block of size[0] × size[1] × size[2] split into n[0] × n[1] × n[2] hexahedral cells,
// centred at the origin.
inline CellMesh tetrahedral_block(std::array<int, 3> n, std::array<double, 3> size) {
  CellMesh mesh;
  auto id = [n](int i, int j, int k) { return (k * (n[1] + 1) + j) * (n[0] + 1) + i; };
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i)
        mesh.nodes.push_back({i * size[0] / n[0] - size[0] / 2, j * size[1] / n[1] - size[1] / 2,
                              k * size[2] / n[2] - size[2] / 2});
  const int axes_orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  auto signed_volume = [&](const std::array<int, 4>& t) {
    double d[3][3];
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) d[a][c] = mesh.nodes[t[a + 1]][c] - mesh.nodes[t[0]][c];
    return d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
           d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]);
  };
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        for (const auto& order : axes_orders) {
          int step[3] = {i, j, k};
          std::array<int, 4> tet{};
          tet[0] = id(i, j, k);
          for (int a = 0; a < 3; ++a) {
            ++step[order[a]];
            tet[a + 1] = id(step[0], step[1], step[2]);
          }
          if (signed_volume(tet) < 0) std::swap(tet[2], tet[3]);
          mesh.tetrahedra.push_back(tet);
        }
  // Faces used by one tetrahedron are on the surface; orient them away from the
  // tetrahedron's fourth node.
  std::map<std::array<int, 3>, std::pair<int, std::array<int, 4>>> faces;
  for (const auto& t : mesh.tetrahedra)
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 4> face_and_opposite{};
      int m = 0;
      for (int a = 0; a < 4; ++a)
        if (a != skip) face_and_opposite[m++] = t[a];
      face_and_opposite[3] = t[skip];
      std::array<int, 3> key{face_and_opposite[0], face_and_opposite[1], face_and_opposite[2]};
      std::sort(key.begin(), key.end());
      auto& entry = faces[key];
      ++entry.first;
      entry.second = face_and_opposite;
    }
  for (const auto& [key, entry] : faces) {
    if (entry.first != 1) continue;
    std::array<int, 4> f = entry.second;
    // (x1−x0)×(x2−x0) must point away from the opposite node f[3].
    if (signed_volume({f[0], f[1], f[2], f[3]}) > 0) std::swap(f[1], f[2]);
    mesh.outer_surface.push_back({f[0], f[1], f[2]});
  }
  return mesh;
}

// The cube [−size/2, size/2]³ split into n³ cubes.
inline CellMesh tetrahedral_box(int n, double size) { return tetrahedral_block({n, n, n}, {size, size, size}); }

}  // namespace rouleau::testing
