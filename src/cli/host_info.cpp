#include "cli/host_info.hpp"

#include <CLI/Version.hpp>
#include <Eigen/Core>
#include <H5public.h>
#include <spdlog/version.h>
#include <toml++/toml.h>

#include "rouleau_version.hpp"

namespace rouleau {
namespace {

std::string dotted_version(int major, int minor, int patch) {
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

}  // namespace

std::vector<std::pair<std::string, std::string>> host_dependency_versions() {
  return {
      {"rouleau", ROULEAU_VERSION},
      {"git", ROULEAU_GIT_HASH},
      {"build type", ROULEAU_BUILD_TYPE},
      {"toml++", dotted_version(TOML_LIB_MAJOR, TOML_LIB_MINOR, TOML_LIB_PATCH)},
      {"CLI11", CLI11_VERSION},
      {"spdlog", dotted_version(SPDLOG_VER_MAJOR, SPDLOG_VER_MINOR, SPDLOG_VER_PATCH)},
      {"Eigen", dotted_version(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"HDF5", dotted_version(H5_VERS_MAJOR, H5_VERS_MINOR, H5_VERS_RELEASE)},
  };
}

}  // namespace rouleau
