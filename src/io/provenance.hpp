#pragma once
// Provenance: where an output file came from (code version, dependency versions, machine,
// time, inputs). Every output file carries these as string attributes (docs/design.md,
// "Provenance"). Host-only: includes no Kokkos header.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace rouleau {

// Ordered (key, value) pairs; keys are unique and non-empty.
struct Provenance {
  std::vector<std::pair<std::string, std::string>> attributes;

  // The value stored under `key`, or nullptr when there is none.
  const std::string* find(const std::string& key) const;

  // Sets `key` to `value`: replaces an existing entry in place, appends otherwise.
  // Throws std::invalid_argument for an empty key.
  void set(const std::string& key, const std::string& value);
};

// The time now in UTC, ISO 8601 ("2024-05-01T12:34:56Z").
std::string current_utc_time_iso8601();

// The provenance of this build and this process: "rouleau_version", "git_hash",
// "kokkos_version", "kokkoskernels_version", "hdf5_version" (the library linked at run
// time, from H5get_libversion), "build_type", "created_utc" (ISO 8601, e.g.
// "2024-05-01T12:34:56Z") and "host_name"; then `extra` (thread count, mesh hashes, case
// name, execution space, ...), whose keys replace built-in ones of the same name.
Provenance build_provenance(const std::vector<std::pair<std::string, std::string>>& extra = {});

// A stable digest of a mesh: 64-bit FNV-1a over the two array lengths and the values'
// little-endian bytes (IEEE-754 doubles, 64-bit integers), as 16 lowercase hex digits.
// The same arrays give the same digest on every machine and build; any changed coordinate
// bit or node index changes it. Either pointer may be null when its count is 0.
std::string hash_mesh(const double* coordinates, std::size_t n_coordinates, const long long* connectivity,
                      std::size_t n_connectivity);

}  // namespace rouleau
