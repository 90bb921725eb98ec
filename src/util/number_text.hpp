#pragma once
// Numbers as text, the two ways rouleau writes them: rounded for a person (error messages,
// the case-file reference) and exact for a file (the resolved case).
// Host-only: includes no Kokkos header.
#include <cstdint>
#include <string>

namespace rouleau {

// `value` to `significant_digits` digits, as printf's %g writes it ("-1", "0.001", "1e-07").
std::string format_number(double value, int significant_digits = 6);
std::string format_number(std::int64_t value);

// `value` as the shortest TOML float that reads back to the same double ("0.0012", "1.0").
std::string toml_float(double value);

}  // namespace rouleau
