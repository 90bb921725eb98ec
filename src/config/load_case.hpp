#pragma once
// Reading a case file (TOML) into a CaseConfig, converting to internal units once.
// Host-only: includes no Kokkos header.
#include <string>
#include <vector>

#include "config/case_config.hpp"
#include "config/case_file_names.hpp"  // toml_name(): the case-file spelling of each choice

namespace rouleau {

// Density in the file is in kg/m³; internally pN·s²/μm⁴ (1000 kg/m³ = 1e-9).
inline constexpr double density_kg_m3_to_internal = 1e-12;

// Loads and validates the case file at `path`, whose keys are those of the key table
// (case_keys.hpp). `overrides` are "dotted.key=value" strings (value parsed as a TOML
// value, or taken as a string when it is not one), applied to the parsed file before
// validation, creating tables as needed. Every key is checked: unknown
// keys and tables, wrong types, wrong array lengths, missing required keys and out-of-range
// values throw InputError(file, dotted.key, reason); errors about an overridden key name
// the file "--set". A missing/unreadable file is InputError(path, "(file)", reason); a TOML
// syntax error is InputError(path, "line L, column C", reason). The [derived] table written
// by resolved_case_toml() is accepted and ignored. Cells are checked last, on their exact
// shapes (check_cell_placement(), cell_placement_check.hpp): each inside the domain and overlapping no other cell.
// Cells: config.cell_kinds holds the built-in kinds (builtin_cell_kinds(), changed by
// [cell_kinds.NAME] tables of their name) and then the kinds the file adds, which start from
// the built-in "normal" cell; errors name cell_kinds.NAME.KEY. config.cells holds the
// [[cells]] entries; errors name cells[I].KEY (I from 0).
CaseConfig load_case(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for a case held in memory (a checkpoint's resolved case, a fuzzer's input):
// `source_name` stands for the file in errors and in config.source_file.
CaseConfig load_case_text(const std::string& text, const std::string& source_name,
                          const std::vector<std::string>& overrides = {});

}  // namespace rouleau
