#pragma once
// Versions of rouleau and of its host-side dependencies, for `rouleau info` and provenance.
// Host-only: includes no Kokkos header.
#include <string>
#include <utility>
#include <vector>

namespace rouleau {

// Name/value pairs: rouleau version, git hash and build type, then the toml++, CLI11,
// spdlog, Eigen and HDF5 versions as compiled in (from their headers).
std::vector<std::pair<std::string, std::string>> host_dependency_versions();

}  // namespace rouleau
