#pragma once
// The case-file reference (docs/case-file.md): every key of the key table with its unit,
// default, allowed values and meaning, as Markdown. `rouleau keys` prints it.
// Host-only: includes no Kokkos header.
#include <string>

namespace rouleau {

// The command that writes docs/case-file.md from the build (a test compares the two).
inline constexpr const char* case_file_reference_command = "build/rouleau keys > docs/case-file.md";

// An introduction (TOML, units, errors, --set), then one section per table of
// case_sections(), in the order of a case file, with a row per key.
std::string case_file_reference();

}  // namespace rouleau
