// Loading a case: the file parsed, the overrides applied, then each table read in the
// order later tables depend on (the kinds before the cells that name them), then the
// checks of the whole case.
#include "config/load_case.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>

#include "config/case_keys.hpp"
#include "config/case_overrides.hpp"
#include "config/case_section_readers.hpp"
#include "config/cell_placement_check.hpp"
#include "util/errors.hpp"

namespace rouleau {
namespace {

// Parses a case's text; a syntax error becomes InputError(source, "line L, column C", reason).
toml::table parse_case_text(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& error) {
    const auto& begin = error.source().begin;
    throw InputError(source, "line " + std::to_string(begin.line) + ", column " + std::to_string(begin.column),
                     "TOML syntax error: " + std::string(error.description()));
  }
}

// Reads the file and parses it; an I/O error becomes InputError(path, "(file)", reason).
toml::table parse_case_file(const std::string& path) {
  std::error_code status;
  if (!std::filesystem::exists(path, status)) throw InputError(path, "(file)", "no such file");
  if (std::filesystem::is_directory(path, status)) throw InputError(path, "(file)", "is a directory, not a case file");
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path, "(file)", std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream contents;
  contents << stream.rdbuf();
  if (stream.bad()) throw InputError(path, "(file)", "cannot read");
  return parse_case_text(contents.str(), path);
}

// The tables a case file may hold at its top: those of the key table, and [derived], which
// resolved_case_toml() writes for the reader (output-only).
std::vector<std::string_view> top_level_table_names() {
  std::vector<std::string_view> names;
  for (const CaseSection& section : case_sections()) {
    const std::string_view top = section.name.substr(0, section.name.find('.'));
    if (std::find(names.begin(), names.end(), top) == names.end()) names.push_back(top);
  }
  names.push_back("derived");
  return names;
}

// The case in `document` (parsed from `path`), with the overrides applied, validated.
CaseConfig load_case_document(toml::table document, const std::string& path, const std::vector<std::string>& overrides) {
  const ErrorSource errors(path, apply_overrides(document, overrides));
  const TableReader root(document, errors, top_level_table_names());
  CaseConfig config;
  config.source_file = path;
  read_case_section(root, path, config);
  read_fluid(root, config.fluid);
  if (root.has("vessel")) {
    if (root.has("domain"))
      root.fail("vessel", "a case has either a [domain] box or a [vessel], not both (remove one of the two tables)");
    read_vessel(root, config.vessel);
    read_vessel_boundaries(root, config.vessel);
  } else {
    read_domain(root, config.domain);
    read_boundaries(root, config.domain);
  }
  read_time(root, config.time);
  read_solver(root, config.solver);
  read_scales(root, config.scales);
  read_output(root, config.output);
  read_checkpoint(root, config.checkpoint);
  read_cell_kinds(root, config.cell_kinds);
  read_cells(root, config);
  read_interaction(root, config);
  read_coupling(root, config.coupling, config.interaction);
  read_scene(root, config.scene);
  // The cells against the domain and each other (exact shapes, before any meshing).
  check_cell_placement(config);
  check_time_step(config);
  check_preconditioner(config);
  return config;
}

}  // namespace

CaseConfig load_case(const std::string& path, const std::vector<std::string>& overrides) {
  return load_case_document(parse_case_file(path), path, overrides);
}

CaseConfig load_case_text(const std::string& text, const std::string& source_name,
                          const std::vector<std::string>& overrides) {
  return load_case_document(parse_case_text(text, source_name), source_name, overrides);
}

}  // namespace rouleau
