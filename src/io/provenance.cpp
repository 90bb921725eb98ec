#include "io/provenance.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <limits.h>
#include <stdexcept>

#include "rouleau_version.hpp"
#include "util/fnv1a.hpp"

namespace rouleau {

const std::string* Provenance::find(const std::string& key) const {
  for (const auto& [existing_key, value] : attributes)
    if (existing_key == key) return &value;
  return nullptr;
}

void Provenance::set(const std::string& key, const std::string& value) {
  if (key.empty()) throw std::invalid_argument("rouleau::Provenance::set: empty key (value \"" + value + "\")");
  for (auto& [existing_key, existing_value] : attributes) {
    if (existing_key == key) {
      existing_value = value;
      return;
    }
  }
  attributes.emplace_back(key, value);
}

namespace {

std::string hdf5_runtime_version() {
  unsigned major = 0, minor = 0, release = 0;
  if (H5get_libversion(&major, &minor, &release) < 0) return "unknown";
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release);
}

}  // namespace

std::string current_utc_time_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

namespace {

std::string host_name() {
  char name[HOST_NAME_MAX + 1] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "unknown";
  return name;
}

}  // namespace

Provenance build_provenance(const std::vector<std::pair<std::string, std::string>>& extra) {
  Provenance provenance;
  provenance.set("rouleau_version", ROULEAU_VERSION);
  provenance.set("git_hash", ROULEAU_GIT_HASH);
  provenance.set("kokkos_version", ROULEAU_KOKKOS_VERSION);
  provenance.set("kokkoskernels_version", ROULEAU_KOKKOSKERNELS_VERSION);
  provenance.set("hdf5_version", hdf5_runtime_version());
  provenance.set("build_type", ROULEAU_BUILD_TYPE);
  provenance.set("created_utc", current_utc_time_iso8601());
  provenance.set("host_name", host_name());
  for (const auto& [key, value] : extra) provenance.set(key, value);
  return provenance;
}

std::string hash_mesh(const double* coordinates, std::size_t n_coordinates, const long long* connectivity,
                      std::size_t n_connectivity) {
  Fnv1a64 hash;
  hash.add_word(n_coordinates);
  hash.add_word(n_connectivity);
  for (std::size_t i = 0; i < n_coordinates; ++i) hash.add_double(coordinates[i]);
  for (std::size_t i = 0; i < n_connectivity; ++i) hash.add_word(static_cast<std::uint64_t>(connectivity[i]));
  return hash.hex_digest();
}

}  // namespace rouleau
