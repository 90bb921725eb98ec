#pragma once
// The bad case files in tests/data/bad_cases each name, on a "# expect-key: KEY" line, the
// dotted key their error must name.
#include <fstream>
#include <string>

namespace {

// The key a bad case file expects in its error.
std::string expected_key_of(const std::string& path) {
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line))
    if (line.rfind("# expect-key: ", 0) == 0) return line.substr(14);
  return {};
}

}  // namespace
