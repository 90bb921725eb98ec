#include "io/diagnostics_reader.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rouleau {

namespace {
std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  return cells;
}
}  // namespace

std::vector<std::map<std::string, double>> read_diagnostics(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("rouleau::read_diagnostics: " + path + ": cannot open");
  std::string header, line;
  std::getline(in, header);
  const auto names = split_csv_line(header);
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto values = split_csv_line(line);
    if (names.size() != values.size())
      throw std::runtime_error("rouleau::read_diagnostics: " + path + ": a row and the header differ in length");
    std::map<std::string, double> row;
    for (size_t i = 0; i < names.size(); ++i) row[names[i]] = std::strtod(values[i].c_str(), nullptr);
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw std::runtime_error("rouleau::read_diagnostics: " + path + ": no data row");
  return rows;
}

std::map<std::string, double> read_last_diagnostics(const std::string& path) { return read_diagnostics(path).back(); }

}  // namespace rouleau
