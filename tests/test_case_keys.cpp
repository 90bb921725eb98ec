// The key table against the loader and the docs: every key of the table is read by the
// loader with the table's type, no key outside it is accepted, its defaults are the ones a
// loaded case has, and docs/case-file.md is the reference rendered from it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <algorithm>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "config/case_file_reference.hpp"
#include "config/case_keys.hpp"
#include "config/derived.hpp"
#include "config/load_case.hpp"
#include "config/resolved_case.hpp"
#include "support/toml_document.hpp"
#include "util/errors.hpp"

namespace {

using rouleau::CaseKey;
using rouleau::InputError;

// A case as its tables' text: header ("[fluid]", "[[cells]]") → key → TOML value, so that
// a test can replace one key's value.
using CaseTables = std::vector<std::pair<std::string, std::map<std::string, std::string>>>;

std::string case_text(const CaseTables& tables) {
  std::string text;
  for (const auto& [header, keys] : tables) {
    text += header + "\n";
    for (const auto& [key, value] : keys) text += key + " = " + value + "\n";
  }
  return text;
}

// A box with a wall, an inflow and a traction side, one cell, a pair law.
const CaseTables box_case{
    {"[domain]", {{"lower_um", "[0, 0, 0]"}, {"upper_um", "[10, 20, 30]"}, {"elements", "[2, 2, 2]"}}},
    {"[boundary.x_min]", {{"type", "\"wall\""}}},
    {"[boundary.y_min]", {{"type", "\"inflow\""}, {"mean_speed_um_s", "1"}}},
    {"[boundary.z_min]", {{"type", "\"traction\""}}},
    {"[time]", {{"dt_s", "0.001"}, {"end_s", "0.01"}}},
    {"[cell_kinds.normal]", {}},
    {"[cell_kinds.bent]", {{"shape", "\"sickle\""}}},
    {"[cell_kinds.rod]", {{"shape", "\"spheroid\""}, {"body", "\"filled\""}}},
    {"[[cells]]", {{"kind", "\"normal\""}, {"center_um", "[5, 10, 15]"}}},
    {"[interaction]", {}},
    {"[[interaction.pair]]", {{"kind_a", "\"normal\""}, {"kind_b", "\"sickle\""}}},
};
// A vessel with an inflow inlet and a traction outlet.
const CaseTables vessel_case{
    {"[vessel]", {{"radius_um", "5"}, {"inlet_length_um", "20"}, {"element_size_um", "1"}}},
    {"[boundary.inlet]", {{"type", "\"inflow\""}, {"mean_speed_um_s", "100"}}},
    {"[boundary.outlet]", {{"type", "\"traction\""}}},
    {"[boundary.wall]", {{"type", "\"wall\""}}},
    {"[time]", {{"dt_s", "0.001"}, {"end_s", "0.01"}}},
};

// Where a key of the table is tried: the base case, its table there, and the dotted key
// errors name. A boundary key goes to a side of the type it belongs to; a sickle's size to
// a sickle kind.
struct KeyPlace {
  const CaseTables* base;
  std::string header;
  std::string dotted_table;
};
KeyPlace place_of(const CaseKey& key) {
  const std::string section(key.section), name(key.name);
  if (section == "boundary.SIDE") {
    const std::string side = name == "velocity_um_s" || name == "type" ? "x_min"
                             : name == "pressure_Pa" || name == "parallel_flow" ? "z_min"
                                                                                : "y_min";
    return {&box_case, "[boundary." + side + "]", "boundary." + side};
  }
  if (section == "boundary.END") {
    const std::string end = name == "pressure_Pa" || name == "parallel_flow" ? "outlet" : "inlet";
    return {&vessel_case, "[boundary." + end + "]", "boundary." + end};
  }
  if (section == "vessel" || section == "boundary.wall") return {&vessel_case, "[" + section + "]", section};
  if (section == "cell_kinds.NAME") {
    const bool sickle_size = name == "length_um" || name == "width_um" || name == "thickness_um" || name == "arc_radius_um";
    const std::string kind = sickle_size ? "bent" : name == "axis_ratio" ? "rod" : "normal";
    return {&box_case, "[cell_kinds." + kind + "]", "cell_kinds." + kind};
  }
  if (section == "cells" || section == "interaction.pair") return {&box_case, "[[" + section + "]]", section + "[0]"};
  return {&box_case, "[" + section + "]", section};
}

// `tables` with `header`'s `key` set to `value` (the table added when absent).
std::string case_with(CaseTables tables, const std::string& header, const std::string& key, const std::string& value) {
  for (auto& [table_header, keys] : tables)
    if (table_header == header) {
      keys[key] = value;
      return case_text(tables);
    }
  tables.push_back({header, {{key, value}}});
  return case_text(tables);
}

// The InputError loading `text` throws, or a test failure.
InputError load_error(const std::string& text) {
  try {
    rouleau::load_case_text(text, "keys.toml");
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return InputError("", "", "");
}

TEST(CaseKeys, TheBaseCasesLoad) {
  EXPECT_NO_THROW(rouleau::load_case_text(case_text(box_case), "box.toml"));
  EXPECT_NO_THROW(rouleau::load_case_text(case_text(vessel_case), "vessel.toml"));
}

// A key the loader never read would let a table value through; a key read as another type
// than the table's would stop the loader with a std::logic_error.
TEST(CaseKeys, TheLoaderReadsEveryKeyOfTheTableWithItsType) {
  for (const CaseKey& key : rouleau::case_keys()) {
    const KeyPlace place = place_of(key);
    const InputError error = load_error(case_with(*place.base, place.header, std::string(key.name), "{ }"));
    EXPECT_EQ(error.key(), place.dotted_table + "." + std::string(key.name)) << error.what();
    EXPECT_EQ(error.reason().rfind("expected ", 0), 0u) << error.what();
    EXPECT_NE(error.reason().find(", got a table"), std::string::npos) << error.what();
  }
}

TEST(CaseKeys, NoKeyOutsideTheTableIsAccepted) {
  for (const rouleau::CaseSection& section : rouleau::case_sections()) {
    const CaseKey& first = *std::find_if(rouleau::case_keys().begin(), rouleau::case_keys().end(),
                                         [&](const CaseKey& key) { return key.section == section.name; });
    const KeyPlace place = place_of(first);
    const InputError error = load_error(case_with(*place.base, place.header, "not_in_the_table", "1"));
    EXPECT_EQ(error.key(), place.dotted_table + ".not_in_the_table") << error.what();
    EXPECT_EQ(error.reason(), "unknown key") << error.what();
  }
}

// The defaults the reference states are those of a case that leaves the key out: the value
// its resolved case (which writes every key that applies) gives.
TEST(CaseKeys, DefaultsAreTheValuesOfACaseWithoutTheKey) {
  const auto resolved = [](const CaseTables& tables) {
    const rouleau::CaseConfig config = rouleau::load_case_text(case_text(tables), "defaults.toml");
    return rouleau::testing::TomlDocument(rouleau::resolved_case_toml(config, rouleau::derive_quantities(config)));
  };
  const rouleau::testing::TomlDocument box = resolved(box_case), vessel = resolved(vessel_case);
  int compared = 0;
  for (const CaseKey& key : rouleau::case_keys()) {
    const KeyPlace place = place_of(key);
    std::string path = place.dotted_table + "." + std::string(key.name);
    if (key.section == "boundary.SIDE") path = "boundary.x_max." + std::string(key.name);  // a side the case leaves out
    if (key.section == "cells" && key.name == "kind") continue;  // the base case gives it
    const rouleau::testing::TomlDocument& document = place.base == &box_case ? box : vessel;
    // Nothing when the reference states no value ("required") or the key does not apply
    // to the kind's shape or the side's type.
    const std::optional<bool> same = document.equals(key.default_value, path);
    if (!same) continue;
    EXPECT_TRUE(*same) << path << ": the reference says " << key.default_value << ", a loaded case has "
                       << document.value_text(path).value_or("nothing");
    ++compared;
  }
  EXPECT_GT(compared, 60);
}

TEST(CaseFileReference, DocsPageIsTheGeneratedOne) {
  const std::string path = std::string(ROULEAU_SOURCE_DIR) + "/docs/case-file.md";
  std::ifstream file(path);
  ASSERT_TRUE(file) << "no " << path << ": write it with " << rouleau::case_file_reference_command;
  std::ostringstream committed;
  committed << file.rdbuf();
  EXPECT_TRUE(committed.str() == rouleau::case_file_reference())
      << "docs/case-file.md differs from the key table's reference; regenerate it with "
      << rouleau::case_file_reference_command;
}

}  // namespace
