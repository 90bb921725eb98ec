#pragma once
// Reading back a diagnostics.csv written by DiagnosticsTable: case drivers and regression
// tests check their scalars from it. Host-only.
#include <map>
#include <string>
#include <vector>

namespace rouleau {

// Every row of the CSV at `path`, each as column name → value. Throws std::runtime_error
// naming the file when it cannot be read, a row does not match the header, or there is no
// data row.
std::vector<std::map<std::string, double>> read_diagnostics(const std::string& path);

// The last row.
std::map<std::string, double> read_last_diagnostics(const std::string& path);

}  // namespace rouleau
