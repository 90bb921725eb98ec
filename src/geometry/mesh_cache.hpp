#pragma once
// The on-disk cache of Gmsh meshes (cells and vessels): one text file per mesh, named by
// the hash of everything that made it, written to a temporary name and renamed.
//
//   <header>               e.g. "rouleau-cell-mesh 1"
//   hash <hash>
//   parameters <canonical text of everything that made the mesh, one line>
//   nodes <N>              then N lines "x y z" [μm], 17 significant digits
//   tetrahedra <T>         then T lines "i j k l", 0-based node indices
//   <surface name> <F>     then F lines "i j k", for each named surface in turn
//   end
// Host-only: includes no Kokkos header.
#include <functional>
#include <istream>
#include <string>
#include <utility>
#include <vector>

#include "geometry/tetrahedral_mesh.hpp"

namespace rouleau {

struct NamedSurface {
  std::string name;
  std::vector<Triangle> triangles;
};

struct CachedMesh {
  TetrahedralMesh mesh;
  std::vector<NamedSurface> surfaces;
};

// The file's text.
std::string serialize_cached_mesh(const std::string& header, const std::string& hash, const std::string& parameters,
                                  const CachedMesh& mesh);

// Reads a cache file's text whose header, hash and parameters lines must be these, with
// the surfaces `surface_names` in this order, each with at least the matching minimum
// count of triangles. Every index must be in range and every tetrahedron must have
// positive volume. Memory stays within a small multiple of the text's size whatever the
// counts claim. Throws std::runtime_error with the reason when anything is off.
CachedMesh parse_cached_mesh(std::istream& in, const std::string& header, const std::string& hash,
                             const std::string& parameters,
                             const std::vector<std::pair<std::string, std::size_t>>& surface_names);

// The same from the file at `path`.
CachedMesh read_cached_mesh(const std::string& path, const std::string& header, const std::string& hash,
                            const std::string& parameters, const std::vector<std::pair<std::string, std::size_t>>& surface_names);

// Writes `text` to directory/file_name through a temporary file of this process and call
// (two processes meshing the same body at once do not share it) and an atomic rename.
void write_mesh_cache_file(const std::string& directory, const std::string& file_name, const std::string& text);

// The mesh stored as directory/file_name when a readable file with this header, hash and
// parameters is there (and `check`, when given, accepts it: it throws with the reason
// otherwise); else make()'s, stored there. An unusable cache file or a failed store is
// warned about, naming `what`, and bypassed: the cache never stops a run.
CachedMesh cached_or_made(const std::string& directory, const std::string& file_name, const std::string& header,
                          const std::string& hash, const std::string& parameters,
                          const std::vector<std::pair<std::string, std::size_t>>& surface_names,
                          const std::string& what, const std::function<CachedMesh()>& make,
                          const std::function<void(const CachedMesh&)>& check = {});

// $ROULEAU_MESH_CACHE when set, else $XDG_CACHE_HOME/rouleau/meshes, else
// $HOME/.cache/rouleau/meshes, else ./.rouleau-mesh-cache.
std::string default_mesh_cache_dir();

}  // namespace rouleau
