#pragma once
// Command-line overrides of case keys: --set dotted.key=value.
// Host-only: includes no Kokkos header.
#include <string>
#include <toml++/toml.h>
#include <vector>

namespace rouleau {

// The "file" named by errors in command-line overrides.
inline constexpr const char* override_source_name = "--set";

// Applies "dotted.key=value" overrides to `document` (the value parsed as a TOML value, or
// taken as a string when it is not one), creating tables as needed; returns the dotted
// keys set. A malformed override is InputError("--set", the override, reason).
std::vector<std::string> apply_overrides(toml::table& document, const std::vector<std::string>& overrides);

}  // namespace rouleau
