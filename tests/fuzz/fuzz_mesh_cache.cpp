// libFuzzer target: the mesh cache reader (geometry/mesh_cache.hpp), which reads the cell
// and vessel meshes a run finds on disk, on arbitrary bytes. The input's own first three
// lines are taken as the header, hash and parameters the reader expects (so a real cache
// file is a valid seed), with the surfaces of a cell mesh or, for a vessel header, of a
// vessel mesh. Every input must either be read or be refused with std::runtime_error; a
// mesh that is read must keep the reader's promises (indices in range, every tetrahedron
// of positive volume, at least the minimum triangles per surface).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "geometry/mesh_cache.hpp"

namespace {
[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_mesh_cache: a mesh was read that %s\n", what);
  std::abort();
}

// The names and minimum triangle counts the cell and vessel meshers ask for
// (geometry/cell_mesh.cpp, geometry/vessel_mesh.cpp).
const std::vector<std::pair<std::string, std::size_t>> cell_surfaces{{"outer_surface", 4}, {"inner_surface", 0}};
const std::vector<std::pair<std::string, std::size_t>> vessel_surfaces{{"inlet", 1}, {"outlet", 1}, {"wall", 1}};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream lines(text);
  std::string header, hash_line, parameters_line;
  std::getline(lines, header);
  std::getline(lines, hash_line);
  std::getline(lines, parameters_line);
  const std::string hash = hash_line.rfind("hash ", 0) == 0 ? hash_line.substr(5) : std::string();
  const std::string parameters = parameters_line.rfind("parameters ", 0) == 0 ? parameters_line.substr(11) : std::string();
  const auto& surfaces = header.rfind("rouleau-vessel-mesh", 0) == 0 ? vessel_surfaces : cell_surfaces;
  std::istringstream in(text);
  rouleau::CachedMesh cached;
  try {
    cached = rouleau::parse_cached_mesh(in, header, hash, parameters, surfaces);
  } catch (const std::runtime_error&) {
    return 0;
  }
  const auto& mesh = cached.mesh;
  const int nodes = static_cast<int>(mesh.nodes.size());
  const auto in_range = [&](int i) { return i >= 0 && i < nodes; };
  for (const auto& t : mesh.tetrahedra) {
    for (int i : t)
      if (!in_range(i)) fail("has a tetrahedron's node index out of range");
    if (!(rouleau::signed_volume6(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]) > 0.0))
      fail("has a tetrahedron without positive volume");
  }
  if (cached.surfaces.size() != surfaces.size()) fail("lacks a surface");
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    if (cached.surfaces[s].triangles.size() < surfaces[s].second) fail("has too few triangles on a surface");
    for (const auto& f : cached.surfaces[s].triangles)
      for (int i : f)
        if (!in_range(i)) fail("has a triangle's node index out of range");
  }
  return 0;
}
