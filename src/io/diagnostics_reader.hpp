#pragma once
// Reading back a diagnostics.csv written by DiagnosticsTable: case drivers and regression
// tests check their scalars from it. Host-only.
#include <map>
#include <string>

namespace rouleau {

// The last row of the CSV at `path` as column name → value. Throws std::runtime_error
// naming the file when it cannot be read or has no data row.
std::map<std::string, double> read_last_diagnostics(const std::string& path);

}  // namespace rouleau
