#include "geometry/mesh_cache.hpp"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace rouleau {

std::string serialize_cached_mesh(const std::string& header, const std::string& hash, const std::string& parameters,
                                  const CachedMesh& cached) {
  const TetrahedralMesh& mesh = cached.mesh;
  std::string text;
  text.reserve(80 * mesh.nodes.size() + 40 * mesh.tetrahedra.size());
  char line[160];
  text += header + "\nhash " + hash + "\nparameters " + parameters + "\n";
  text += "nodes " + std::to_string(mesh.nodes.size()) + "\n";
  for (const auto& x : mesh.nodes) {
    std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", x[0], x[1], x[2]);
    text += line;
  }
  text += "tetrahedra " + std::to_string(mesh.tetrahedra.size()) + "\n";
  for (const auto& t : mesh.tetrahedra) {
    std::snprintf(line, sizeof line, "%d %d %d %d\n", t[0], t[1], t[2], t[3]);
    text += line;
  }
  for (const NamedSurface& surface : cached.surfaces) {
    text += surface.name + " " + std::to_string(surface.triangles.size()) + "\n";
    for (const auto& f : surface.triangles) {
      std::snprintf(line, sizeof line, "%d %d %d\n", f[0], f[1], f[2]);
      text += line;
    }
  }
  text += "end\n";
  return text;
}

CachedMesh parse_cached_mesh(std::istream& in, const std::string& header, const std::string& hash,
                             const std::string& parameters,
                             const std::vector<std::pair<std::string, std::size_t>>& surface_names) {
  std::string line;
  const auto expect_line = [&](const std::string& wanted, const char* what) {
    if (!std::getline(in, line) || line != wanted) throw std::runtime_error(std::string("wrong ") + what + " line");
  };
  expect_line(header, "header");
  expect_line("hash " + hash, "hash");
  expect_line("parameters " + parameters, "parameters");
  const auto read_count = [&](const std::string& keyword, std::size_t minimum) {
    std::string word;
    long long count = -1;
    if (!(in >> word >> count) || word != keyword || count < static_cast<long long>(minimum) || count > 100000000)
      throw std::runtime_error("bad \"" + keyword + "\" count");
    return static_cast<std::size_t>(count);
  };
  // Entries are appended as they are read, never allocated from a count alone: a file
  // that claims 10^8 nodes must hold them, so memory stays bounded by the file's size.
  constexpr std::size_t reserve_at_most = 1 << 16;
  CachedMesh cached;
  TetrahedralMesh& mesh = cached.mesh;
  const std::size_t node_count = read_count("nodes", 4);
  mesh.nodes.reserve(std::min(node_count, reserve_at_most));
  for (std::size_t n = 0; n < node_count; ++n) {
    MeshPoint x;
    if (!(in >> x[0] >> x[1] >> x[2]) || !std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
      throw std::runtime_error("a node's coordinates are missing or not finite");
    mesh.nodes.push_back(x);
  }
  const auto valid_index = [&](int i) { return i >= 0 && i < static_cast<int>(node_count); };
  const std::size_t tetrahedron_count = read_count("tetrahedra", 1);
  mesh.tetrahedra.reserve(std::min(tetrahedron_count, reserve_at_most));
  for (std::size_t e = 0; e < tetrahedron_count; ++e) {
    Tetrahedron t;
    if (!(in >> t[0] >> t[1] >> t[2] >> t[3]) || !valid_index(t[0]) || !valid_index(t[1]) || !valid_index(t[2]) ||
        !valid_index(t[3]))
      throw std::runtime_error("a tetrahedron's node indices are missing or out of range");
    if (!(signed_volume6(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]) > 0.0))
      throw std::runtime_error("a tetrahedron has no positive volume");
    mesh.tetrahedra.push_back(t);
  }
  for (const auto& [name, minimum] : surface_names) {
    NamedSurface surface{name, {}};
    const std::size_t triangle_count = read_count(name, minimum);
    surface.triangles.reserve(std::min(triangle_count, reserve_at_most));
    for (std::size_t f = 0; f < triangle_count; ++f) {
      Triangle triangle;
      if (!(in >> triangle[0] >> triangle[1] >> triangle[2]) || !valid_index(triangle[0]) ||
          !valid_index(triangle[1]) || !valid_index(triangle[2]))
        throw std::runtime_error("a triangle of \"" + name + "\" has node indices missing or out of range");
      surface.triangles.push_back(triangle);
    }
    cached.surfaces.push_back(std::move(surface));
  }
  std::string word;
  if (!(in >> word) || word != "end") throw std::runtime_error("no \"end\" line (truncated?)");
  if (in >> word) throw std::runtime_error("text after \"end\"");
  return cached;
}

CachedMesh read_cached_mesh(const std::string& path, const std::string& header, const std::string& hash,
                            const std::string& parameters,
                            const std::vector<std::pair<std::string, std::size_t>>& surface_names) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open it");
  return parse_cached_mesh(in, header, hash, parameters, surface_names);
}

void write_mesh_cache_file(const std::string& directory, const std::string& file_name, const std::string& text) {
  namespace fs = std::filesystem;
  fs::create_directories(directory);
  const fs::path path = fs::path(directory) / file_name;
  // A temporary name of this process and call, so that two processes meshing the same
  // body at once do not write into one file; rename is atomic within the directory.
  static std::atomic<unsigned> calls{0};
  const std::string temporary =
      path.string() + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(calls.fetch_add(1));
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw std::runtime_error("cannot write " + temporary);
    }
  }
  try {
    commit_temporary_file(temporary, path.string());
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

CachedMesh cached_or_made(const std::string& directory, const std::string& file_name, const std::string& header,
                          const std::string& hash, const std::string& parameters,
                          const std::vector<std::pair<std::string, std::size_t>>& surface_names,
                          const std::string& what, const std::function<CachedMesh()>& make,
                          const std::function<void(const CachedMesh&)>& check) {
  const std::string path = (std::filesystem::path(directory) / file_name).string();
  std::error_code error;
  if (std::filesystem::exists(path, error)) {
    try {
      CachedMesh cached = read_cached_mesh(path, header, hash, parameters, surface_names);
      if (check) check(cached);
      return cached;
    } catch (const std::exception& bad) {
      spdlog::warn("mesh cache file {} of {} is unusable ({}); meshing again", path, what, bad.what());
    }
  }
  CachedMesh made = make();
  try {
    write_mesh_cache_file(directory, file_name, serialize_cached_mesh(header, hash, parameters, made));
  } catch (const std::exception& failure) {
    spdlog::warn("could not store the mesh of {} in the cache {}: {}", what, directory, failure.what());
  }
  return made;
}

std::string default_mesh_cache_dir() {
  const auto non_empty = [](const char* name) {
    const char* value = std::getenv(name);
    return value && *value ? std::string(value) : std::string();
  };
  if (auto dir = non_empty("ROULEAU_MESH_CACHE"); !dir.empty()) return dir;
  if (auto dir = non_empty("XDG_CACHE_HOME"); !dir.empty()) return dir + "/rouleau/meshes";
  if (auto dir = non_empty("HOME"); !dir.empty()) return dir + "/.cache/rouleau/meshes";
  return "./.rouleau-mesh-cache";
}

}  // namespace rouleau
