#include "config/load_case.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <toml++/toml.h>
#include <utility>

#include "config/cell_kinds.hpp"
#include "config/derived.hpp"
#include "config/cell_placement_check.hpp"
#include "util/errors.hpp"

namespace rouleau {
namespace {

constexpr std::array<const char*, 3> axis_names{"x", "y", "z"};

// A number as it appears in an error message ("-1", "0.001", "1e-07").
std::string format_number(double value) {
  std::ostringstream text;
  text << std::setprecision(6) << value;
  return text.str();
}
std::string format_number(std::int64_t value) { return std::to_string(value); }

// "a string", "an integer", ... for "expected X, got Y" messages.
std::string type_phrase(toml::node_type type) {
  switch (type) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

// Levenshtein distance between two short names.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

// "; did you mean "X"?" for the closest candidate within edit distance 2, else "".
std::string suggestion(std::string_view given, const std::vector<std::string_view>& candidates) {
  std::string_view best;
  std::size_t best_distance = 3;
  for (const auto candidate : candidates) {
    const std::size_t distance = edit_distance(given, candidate);
    if (distance < best_distance) best = candidate, best_distance = distance;
  }
  return best.empty() ? std::string() : "; did you mean \"" + std::string(best) + "\"?";
}

// The names separated by ", ", each in double quotes when `quoted`.
std::string joined(const std::vector<std::string_view>& names, bool quoted) {
  const std::string quote = quoted ? "\"" : "";
  std::string text;
  for (const auto name : names) text += (text.empty() ? "" : ", ") + quote + std::string(name) + quote;
  return text;
}

// An allowed interval of values; describe() gives "> 0", "≥ 1 and ≤ 4096", ...
struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  bool lower_inclusive = true;
  double upper = std::numeric_limits<double>::infinity();
  bool upper_inclusive = true;

  static Range any() { return {}; }
  static Range above(double bound) { return {bound, false}; }
  static Range at_least(double bound) { return {bound, true}; }
  static Range closed(double low, double high) { return {low, true, high, true}; }
  static Range open(double low, double high) { return {low, false, high, false}; }

  bool contains(double value) const {
    const bool above_lower = lower_inclusive ? value >= lower : value > lower;
    const bool below_upper = upper_inclusive ? value <= upper : value < upper;
    return above_lower && below_upper;
  }
  std::string describe() const {
    std::string text;
    if (std::isfinite(lower)) text += (lower_inclusive ? "≥ " : "> ") + format_number(lower);
    if (std::isfinite(upper)) {
      if (!text.empty()) text += " and ";
      text += (upper_inclusive ? "≤ " : "< ") + format_number(upper);
    }
    return text;
  }
};

// Reports errors with the right "file": the case file, or "--set" for keys that came
// from a command-line override (or lie under / above one).
class ErrorSource {
 public:
  ErrorSource(std::string file, std::vector<std::string> overridden_keys)
      : file_(std::move(file)), overridden_keys_(std::move(overridden_keys)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& reason) const {
    throw InputError(file_for(key), key, reason);
  }

 private:
  std::string file_for(const std::string& key) const {
    const auto related = [&](const std::string& overridden) {
      const auto is_prefix = [](const std::string& prefix, const std::string& text) {
        return text.size() > prefix.size() && text.compare(0, prefix.size(), prefix) == 0 &&
               (text[prefix.size()] == '.' || text[prefix.size()] == '[');  // a sub-key or an array entry
      };
      return key == overridden || is_prefix(overridden, key) || is_prefix(key, overridden);
    };
    const bool from_override = std::any_of(overridden_keys_.begin(), overridden_keys_.end(), related);
    return from_override ? override_source_name : file_;
  }

  std::string file_;
  std::vector<std::string> overridden_keys_;
};

// One table of the case file. The constructor rejects keys that are not in `allowed_keys`
// (suggesting the closest); the readers return typed values at the table's keys, checking
// type, array length and range, and report errors with the dotted key.
class TableReader {
 public:
  TableReader(const toml::table* table, std::string path, const ErrorSource& errors,
              std::vector<std::string_view> allowed_keys)
      : table_(table ? table : &empty_table()), path_(std::move(path)), errors_(errors),
        allowed_keys_(std::move(allowed_keys)) {
    for (const auto& [key, node] : *table_) {
      const std::string_view name = key.str();
      if (std::find(allowed_keys_.begin(), allowed_keys_.end(), name) != allowed_keys_.end()) continue;
      fail(name, std::string(node.is_table() ? "unknown table" : "unknown key") + suggestion(name, allowed_keys_));
    }
  }

  // The dotted key of `key` in this table.
  std::string path_of(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }
  [[noreturn]] void fail(std::string_view key, const std::string& reason) const {
    errors_.fail(path_of(key), reason);
  }
  // The keys present in the file, in file order.
  std::vector<std::string> present_keys() const {
    std::vector<std::string> keys;
    for (const auto& [key, node] : *table_) keys.emplace_back(key.str());
    return keys;
  }

  // A sub-table with its own allowed keys; an absent table reads as empty.
  TableReader table(std::string_view key, std::vector<std::string_view> allowed_keys) const {
    const toml::node* found = node(key);
    if (found && !found->is_table()) expected(key, "a table", *found);
    return TableReader(found ? found->as_table() : nullptr, path_of(key), errors_, std::move(allowed_keys));
  }
  // A sub-table whose keys are names the file chooses (such as [cell_kinds.NAME]); every
  // key is allowed. An absent table reads as empty.
  TableReader table_of_names(std::string_view key) const {
    const toml::node* found = node(key);
    if (found && !found->is_table()) expected(key, "a table", *found);
    std::vector<std::string_view> names;
    if (found)
      for (const auto& [name, value] : *found->as_table()) names.push_back(name.str());
    return TableReader(found ? found->as_table() : nullptr, path_of(key), errors_, std::move(names));
  }
  // The entries of an array of tables ([[key]]), each with its own `allowed_keys` and the
  // dotted key "key[I]" (I from 0). An absent array reads as empty.
  std::vector<TableReader> array_of_tables(std::string_view key, const std::vector<std::string_view>& allowed_keys) const {
    const toml::node* found = node(key);
    if (!found) return {};
    const std::string what = "an array of tables ([[" + path_of(key) + "]] entries)";
    if (!found->is_array()) expected(key, what, *found);
    const toml::array& elements = *found->as_array();
    std::vector<TableReader> entries;
    for (std::size_t i = 0; i < elements.size(); ++i) {
      const std::string entry_key = std::string(key) + "[" + std::to_string(i) + "]";
      if (!elements.get(i)->is_table()) expected(entry_key, "a table (an entry of " + what + ")", *elements.get(i));
      entries.emplace_back(elements.get(i)->as_table(), path_of(entry_key), errors_, allowed_keys);
    }
    return entries;
  }
  // Whether the file gives `key`.
  bool has(std::string_view key) const { return node(key) != nullptr; }

  // A finite number (integers accepted) in `range`.
  std::optional<double> number(std::string_view key, const Range& range = Range::any()) const {
    const toml::node* found = node(key);
    if (!found) return std::nullopt;
    const double value = number_value(key, *found, "");
    check_range(key, value, range, "");
    return value;
  }
  // An integer in `range` that fits an int.
  std::optional<int> integer(std::string_view key, const Range& range) const {
    const toml::node* found = node(key);
    if (!found) return std::nullopt;
    const std::int64_t value = integer_value(key, *found, "");
    check_range(key, value, range, "");
    return static_cast<int>(value);
  }
  std::optional<bool> boolean(std::string_view key) const {
    const toml::node* found = node(key);
    if (!found) return std::nullopt;
    if (!found->is_boolean()) expected(key, "a boolean (true or false)", *found);
    return found->as_boolean()->get();
  }
  std::optional<std::string> string(std::string_view key) const {
    const toml::node* found = node(key);
    if (!found) return std::nullopt;
    if (!found->is_string()) expected(key, "a string", *found);
    return found->as_string()->get();
  }
  // An array of 3 finite numbers, each in `range`.
  std::optional<std::array<double, 3>> number3(std::string_view key, const Range& range = Range::any()) const {
    return triple<double>(key, "numbers", range, [&](const toml::node& element, const std::string& label) {
      return number_value(key, element, label);
    });
  }
  // An array of 3 integers, each in `range`.
  std::optional<std::array<std::int64_t, 3>> integer3(std::string_view key, const Range& range) const {
    return triple<std::int64_t>(key, "integers", range, [&](const toml::node& element, const std::string& label) {
      return integer_value(key, element, label);
    });
  }
  // One of the named `choices` (a string).
  template <class Enum>
  std::optional<Enum> choice(std::string_view key, const std::vector<std::pair<std::string_view, Enum>>& choices) const {
    const std::optional<std::string> name = string(key);
    if (!name) return std::nullopt;
    std::vector<std::string_view> names;
    for (const auto& [choice_name, value] : choices) {
      if (choice_name == *name) return value;
      names.push_back(choice_name);
    }
    fail(key, "must be one of " + joined(names, true) + "; got \"" + *name + "\"" + suggestion(*name, names));
  }

 private:
  static const toml::table& empty_table() {
    static const toml::table empty;
    return empty;
  }
  const toml::node* node(std::string_view key) const {
    if (std::find(allowed_keys_.begin(), allowed_keys_.end(), key) == allowed_keys_.end())
      throw std::logic_error("rouleau::load_case: reading undeclared key " + path_of(key));
    return table_->get(key);
  }
  [[noreturn]] void expected(std::string_view key, const std::string& what, const toml::node& found,
                             const std::string& label = "") const {
    fail(key, label + "expected " + what + ", got " + type_phrase(found.type()));
  }
  double number_value(std::string_view key, const toml::node& found, const std::string& label) const {
    if (found.is_integer()) return static_cast<double>(found.as_integer()->get());
    if (!found.is_floating_point()) expected(key, "a number", found, label);
    const double value = found.as_floating_point()->get();
    if (!std::isfinite(value)) fail(key, label + "must be a finite number, got " + format_number(value));
    return value;
  }
  std::int64_t integer_value(std::string_view key, const toml::node& found, const std::string& label) const {
    if (!found.is_integer()) expected(key, "an integer", found, label);
    const std::int64_t value = found.as_integer()->get();
    if (value > std::numeric_limits<int>::max() || value < std::numeric_limits<int>::min())
      fail(key, label + "out of the range of a 32-bit integer, got " + format_number(value));
    return value;
  }
  template <class Number>
  void check_range(std::string_view key, Number value, const Range& range, const std::string& label) const {
    if (!range.contains(static_cast<double>(value)))
      fail(key, label + "must be " + range.describe() + ", got " + format_number(value));
  }
  template <class Number, class ReadElement>
  std::optional<std::array<Number, 3>> triple(std::string_view key, const std::string& element_kind,
                                              const Range& range, ReadElement read_element) const {
    const toml::node* found = node(key);
    if (!found) return std::nullopt;
    const std::string what = "an array of 3 " + element_kind;
    if (!found->is_array()) expected(key, what, *found);
    const toml::array& elements = *found->as_array();
    if (elements.size() != 3) fail(key, "expected " + what + ", got " + std::to_string(elements.size()) + " elements");
    std::array<Number, 3> values{};
    for (std::size_t i = 0; i < 3; ++i) {
      const std::string label = "component " + std::string(axis_names[i]) + ": ";
      values[i] = read_element(*elements.get(i), label);
      check_range(key, values[i], range, label);
    }
    return values;
  }

  const toml::table* table_;
  std::string path_;
  const ErrorSource& errors_;
  std::vector<std::string_view> allowed_keys_;
};

// The choices of an enum as (file spelling, value) pairs.
template <class Enum>
std::vector<std::pair<std::string_view, Enum>> choices_of(std::initializer_list<Enum> values) {
  std::vector<std::pair<std::string_view, Enum>> choices;
  for (const Enum value : values) choices.emplace_back(toml_name(value), value);
  return choices;
}

// Sets `target` when the key was present.
template <class Target, class Value>
void assign(Target& target, const std::optional<Value>& value) {
  if (value) target = static_cast<Target>(*value);
}
template <class Target, class Value>
void assign(std::array<Target, 3>& target, const std::optional<std::array<Value, 3>>& value) {
  if (value)
    for (std::size_t i = 0; i < 3; ++i) target[i] = static_cast<Target>((*value)[i]);
}
template <class Value>
Value require(const TableReader& table, std::string_view key, const std::optional<Value>& value) {
  if (!value) table.fail(key, "missing required key");
  return *value;
}

bool contains(const std::vector<std::string_view>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// The key density_kg_m3 of a section (> 0), converted to pN·s²/μm⁴.
std::optional<double> read_density(const TableReader& section) {
  const auto density = section.number("density_kg_m3", Range::above(0));
  if (!density) return std::nullopt;
  return *density * density_kg_m3_to_internal;
}

// Reads the file and parses it; I/O and syntax errors become InputError.
toml::table parse_case_text(const std::string& text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& error) {
    const auto& begin = error.source().begin;
    throw InputError(source, "line " + std::to_string(begin.line) + ", column " + std::to_string(begin.column),
                     "TOML syntax error: " + std::string(error.description()));
  }
}

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

// Parses the value of an override: a TOML value, or the text itself as a string.
toml::table parse_override_value(const std::string& value_text) {
  try {
    toml::table parsed = toml::parse("value = " + value_text);
    if (parsed.size() == 1 && parsed.contains("value")) return parsed;
  } catch (const toml::parse_error&) {
    // not a TOML value: a bare word such as `steady`
  }
  toml::table as_string;
  as_string.insert("value", value_text);
  return as_string;
}

std::string trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return std::string(text.substr(first, last - first + 1));
}

// Applies "dotted.key=value" overrides to the document; returns the dotted keys set.
std::vector<std::string> apply_overrides(toml::table& document, const std::vector<std::string>& overrides) {
  std::vector<std::string> overridden_keys;
  for (const std::string& text : overrides) {
    const auto equals = text.find('=');
    const std::string key_text = trimmed(std::string_view(text).substr(0, equals));
    if (equals == std::string::npos || key_text.empty())
      throw InputError(override_source_name, text.empty() ? "(empty)" : text,
                       "expected KEY=VALUE with a dotted key, such as time.dt_s=0.01");
    std::vector<std::string> parts;
    for (std::size_t start = 0;;) {
      const auto dot = key_text.find('.', start);
      parts.push_back(key_text.substr(start, dot - start));
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
    const bool bare_key_parts = std::all_of(parts.begin(), parts.end(), is_bare_toml_key);
    if (!bare_key_parts)
      throw InputError(override_source_name, key_text, "not a dotted key (letters, digits, '_' and '-' between dots)");

    toml::table* table = &document;
    std::string path;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      path += (path.empty() ? "" : ".") + parts[i];
      toml::node* child = table->get(parts[i]);
      if (!child) child = &table->insert(parts[i], toml::table{}).first->second;
      if (!child->is_table())
        throw InputError(override_source_name, path, "is " + type_phrase(child->type()) + ", not a table; cannot set " + key_text);
      table = child->as_table();
    }
    toml::table parsed = parse_override_value(trimmed(std::string_view(text).substr(equals + 1)));
    parsed.get("value")->visit([&](auto& value) { table->insert_or_assign(parts.back(), std::move(value)); });
    overridden_keys.push_back(key_text);
  }
  return overridden_keys;
}

void read_case_section(const TableReader& root, const std::string& path, CaseConfig& config) {
  const TableReader section = root.table("case", {"name", "description"});
  config.name = section.string("name").value_or(std::filesystem::path(path).stem().string());
  if (config.name.empty()) section.fail("name", "must not be empty");
  assign(config.description, section.string("description"));
}

void read_fluid(const TableReader& root, FluidConfig& fluid) {
  const TableReader section = root.table("fluid", {"density_kg_m3", "viscosity_Pa_s", "body_force_Pa_um"});
  assign(fluid.density, read_density(section));
  assign(fluid.viscosity, section.number("viscosity_Pa_s", Range::above(0)));
  assign(fluid.body_force, section.number3("body_force_Pa_um"));
}

void read_domain(const TableReader& root, DomainConfig& domain) {
  const TableReader section = root.table("domain", {"lower_um", "upper_um", "elements", "wall_grading"});
  domain.lower = require(section, "lower_um", section.number3("lower_um"));
  domain.upper = require(section, "upper_um", section.number3("upper_um"));
  for (std::size_t axis = 0; axis < 3; ++axis)
    if (!(domain.upper[axis] > domain.lower[axis]))
      section.fail("upper_um", "component " + std::string(axis_names[axis]) + ": must be > lower_um's " +
                                   format_number(domain.lower[axis]) + ", got " + format_number(domain.upper[axis]));
  const auto elements = section.integer3("elements", Range::closed(1, 4096));
  require(section, "elements", elements);
  assign(domain.elements, elements);
  assign(domain.wall_grading, section.number3("wall_grading", Range::closed(1, 100)));
}

// The keys a side of each boundary type takes (besides "type").
std::vector<std::string_view> boundary_keys_of(BoundaryType type) {
  switch (type) {
    case BoundaryType::periodic: return {};
    case BoundaryType::wall: return {"velocity_um_s"};
    case BoundaryType::inflow: return {"mean_speed_um_s", "profile"};
    case BoundaryType::traction: return {"pressure_Pa", "parallel_flow"};
  }
  return {};
}

void read_boundaries(const TableReader& root, DomainConfig& domain) {
  const TableReader boundaries =
      root.table("boundary", std::vector<std::string_view>(side_names.begin(), side_names.end()));
  for (int side = 0; side < 6; ++side) {
    const TableReader reader = boundaries.table(
        side_names[side], {"type", "velocity_um_s", "mean_speed_um_s", "profile", "pressure_Pa", "parallel_flow"});
    BoundaryConfig& boundary = domain.boundary[side];
    assign(boundary.type, reader.choice("type", choices_of({BoundaryType::periodic, BoundaryType::wall,
                                                                 BoundaryType::inflow, BoundaryType::traction})));
    const std::vector<std::string_view> allowed = boundary_keys_of(boundary.type);
    for (const std::string& key : reader.present_keys()) {
      if (key == "type" || contains(allowed, key)) continue;
      reader.fail(key, "does not belong to boundary type \"" + std::string(toml_name(boundary.type)) + "\" (it takes " +
                           (allowed.empty() ? std::string("no key besides type") : joined(allowed, false)) + ")");
    }
    const int axis = side / 2;
    assign(boundary.velocity, reader.number3("velocity_um_s"));
    if (boundary.velocity[axis] != 0.0)
      reader.fail("velocity_um_s", "component " + std::string(axis_names[axis]) +
                                       ": must be 0 (a wall does not move through itself; use type = \"inflow\"), got " +
                                       format_number(boundary.velocity[axis]));
    const auto mean_speed = reader.number("mean_speed_um_s", Range::above(0));
    if (boundary.type == BoundaryType::inflow) require(reader, "mean_speed_um_s", mean_speed);
    assign(boundary.mean_speed, mean_speed);
    assign(boundary.profile,
           reader.choice("profile", choices_of({InflowProfile::uniform, InflowProfile::parabolic})));
    assign(boundary.pressure, reader.number("pressure_Pa"));
    assign(boundary.parallel_flow, reader.boolean("parallel_flow"));
  }
  for (int axis = 0; axis < 3; ++axis) {
    const int low = 2 * axis, high = 2 * axis + 1;
    const bool low_periodic = domain.boundary[low].type == BoundaryType::periodic;
    const bool high_periodic = domain.boundary[high].type == BoundaryType::periodic;
    if (low_periodic != high_periodic) {
      const int lonely = low_periodic ? high : low, partner = low_periodic ? low : high;
      boundaries.fail(std::string(side_names[lonely]) + ".type", std::string("must be \"periodic\" because boundary.") + side_names[partner] +
                                      " is periodic (periodic sides come in pairs)");
    }
    if (low_periodic && domain.elements[axis] < 2)
      root.fail("domain.elements", std::string("component ") + axis_names[axis] +
                                       ": must be ≥ 2 along a periodic direction, got " +
                                       std::to_string(domain.elements[axis]));
  }
}

void read_vessel(const TableReader& root, VesselConfig& vessel) {
  const TableReader section =
      root.table("vessel", {"radius_um", "throat_radius_um", "inlet_length_um", "contraction_length_um",
                            "throat_length_um", "diffuser_length_um", "outlet_length_um", "transition",
                            "element_size_um", "wall_element_size_um", "allow_squeeze", "wall_repulsion_Pa",
                            "wall_repulsion_range_um"});
  vessel.enabled = true;
  VesselProfile& p = vessel.profile;
  p.radius = require(section, "radius_um", section.number("radius_um"));
  p.throat_radius = section.number("throat_radius_um").value_or(p.radius);
  p.inlet_length = require(section, "inlet_length_um", section.number("inlet_length_um"));
  p.contraction_length = section.number("contraction_length_um").value_or(0.0);
  p.throat_length = section.number("throat_length_um").value_or(0.0);
  p.diffuser_length = section.number("diffuser_length_um").value_or(0.0);
  p.outlet_length = section.number("outlet_length_um").value_or(0.0);
  assign(p.transition, section.choice("transition", choices_of({VesselTransition::cosine, VesselTransition::cone})));
  if (const auto problem = vessel_profile_problem(p)) section.fail(problem->key, problem->reason);
  vessel.sizes.element_size = require(section, "element_size_um", section.number("element_size_um"));
  vessel.sizes.wall_element_size = section.number("wall_element_size_um").value_or(0.0);
  if (const auto problem = vessel_mesh_sizes_problem(p, vessel.sizes)) section.fail(problem->key, problem->reason);
  assign(vessel.allow_squeeze, section.boolean("allow_squeeze"));
  assign(vessel.wall_repulsion_pressure, section.number("wall_repulsion_Pa", Range::at_least(0)));
  assign(vessel.wall_repulsion_range, section.number("wall_repulsion_range_um", Range::above(0)));
  if (!(vessel.wall_repulsion_range < p.throat_radius))
    section.fail("wall_repulsion_range_um", "must be below the throat's radius " + format_number(p.throat_radius) +
                                                " μm (it is a short-range force)");
}

// [boundary.inlet] (inflow or traction), [boundary.outlet] (traction), [boundary.wall]
// (type "wall" only: the vessel's wall does not move).
void read_vessel_boundaries(const TableReader& root, VesselConfig& vessel) {
  const TableReader boundaries = root.table("boundary", {"inlet", "outlet", "wall"});
  const auto read_end = [&](const char* name, BoundaryConfig& boundary,
                            std::vector<std::pair<std::string_view, BoundaryType>> types) {
    if (!boundaries.has(name))
      boundaries.fail(name, std::string("missing: a vessel needs [boundary.") + name + "] (type = " +
                                (types.size() > 1 ? "\"inflow\" or \"traction\"" : "\"traction\"") + ")");
    const TableReader reader =
        boundaries.table(name, {"type", "mean_speed_um_s", "profile", "pressure_Pa", "parallel_flow"});
    boundary.type = require(reader, "type", reader.choice("type", types));
    const std::vector<std::string_view> allowed = boundary_keys_of(boundary.type);
    for (const std::string& key : reader.present_keys())
      if (key != "type" && !contains(allowed, key))
        reader.fail(key, "does not belong to boundary type \"" + std::string(toml_name(boundary.type)) +
                             "\" (it takes " + joined(allowed, false) + ")");
    const auto mean_speed = reader.number("mean_speed_um_s", Range::above(0));
    if (boundary.type == BoundaryType::inflow) require(reader, "mean_speed_um_s", mean_speed);
    assign(boundary.mean_speed, mean_speed);
    assign(boundary.profile, reader.choice("profile", choices_of({InflowProfile::uniform, InflowProfile::parabolic})));
    assign(boundary.pressure, reader.number("pressure_Pa"));
    assign(boundary.parallel_flow, reader.boolean("parallel_flow"));
  };
  read_end("inlet", vessel.inlet, choices_of({BoundaryType::inflow, BoundaryType::traction}));
  read_end("outlet", vessel.outlet, choices_of({BoundaryType::traction}));
  const TableReader wall = boundaries.table("wall", {"type"});
  (void)wall.choice("type", choices_of({BoundaryType::wall}));
}

void read_time(const TableReader& root, TimeConfig& time) {
  const TableReader section = root.table("time", {"mode", "scheme", "dt_s", "end_s"});
  assign(time.mode, section.choice("mode", choices_of({TimeMode::steady, TimeMode::transient})));
  assign(time.scheme, section.choice("scheme", choices_of({TimeScheme::bdf2, TimeScheme::backward_euler})));
  const auto dt = section.number("dt_s", Range::above(0));
  const auto end = section.number("end_s", Range::above(0));
  if (time.mode == TimeMode::transient) {
    require(section, "dt_s", dt);
    require(section, "end_s", end);
  }
  assign(time.dt, dt);
  assign(time.end, end);
  if (time.end < time.dt)
    section.fail("end_s", "must be ≥ dt_s (" + format_number(time.dt) + "), got " + format_number(time.end));
}

void read_solver(const TableReader& root, SolverConfig& solver) {
  const TableReader section = root.table(
      "solver", {"stokes", "stokes_reynolds_threshold", "newton_rtol", "newton_atol", "newton_step_rtol", "newton_max_iterations",
                 "gmres_restart", "gmres_rtol", "gmres_max_iterations", "preconditioner"});
  assign(solver.stokes, section.choice("stokes", choices_of({StokesChoice::automatic, StokesChoice::on, StokesChoice::off})));
  assign(solver.stokes_reynolds_threshold, section.number("stokes_reynolds_threshold", Range::above(0)));
  assign(solver.newton_rtol, section.number("newton_rtol", Range::open(0, 1)));
  assign(solver.newton_atol, section.number("newton_atol", Range::at_least(0)));
  assign(solver.newton_step_rtol, section.number("newton_step_rtol", Range::at_least(0)));
  const Range iteration_count = Range::at_least(1);
  assign(solver.newton_max_iterations, section.integer("newton_max_iterations", iteration_count));
  assign(solver.gmres_restart, section.integer("gmres_restart", Range::closed(1, 1000)));
  assign(solver.gmres_rtol, section.number("gmres_rtol", Range::open(0, 1)));
  assign(solver.gmres_max_iterations, section.integer("gmres_max_iterations", iteration_count));
  assign(solver.preconditioner,
         section.choice("preconditioner", choices_of({PreconditionerType::ilu0, PreconditionerType::multigrid, PreconditionerType::block_jacobi,
                                                               PreconditionerType::none})));
}

void read_scales(const TableReader& root, ScalesConfig& scales) {
  const TableReader section = root.table("scales", {"length_um", "velocity_um_s"});
  assign(scales.length, section.number("length_um", Range::at_least(0)));
  assign(scales.velocity, section.number("velocity_um_s", Range::at_least(0)));
}

void read_output(const TableReader& root, OutputConfig& output) {
  const TableReader section =
      root.table("output", {"fields", "fields_every_steps", "diagnostics_every_steps", "cell_gaps_max_cells"});
  const Range step_count = Range::at_least(1);
  assign(output.write_fields, section.boolean("fields"));
  assign(output.fields_every_steps, section.integer("fields_every_steps", step_count));
  assign(output.diagnostics_every_steps, section.integer("diagnostics_every_steps", step_count));
  assign(output.cell_gaps_max_cells, section.integer("cell_gaps_max_cells", Range::at_least(0)));
}

void read_checkpoint(const TableReader& root, CheckpointConfig& checkpoint) {
  const TableReader section = root.table("checkpoint", {"every_steps", "every_minutes", "keep"});
  assign(checkpoint.every_steps, section.integer("every_steps", Range::at_least(0)));
  assign(checkpoint.every_minutes, section.number("every_minutes", Range::at_least(0)));
  assign(checkpoint.kept, section.integer("keep", Range::closed(1, 1000)));
}

// ---- cells

// Every key a [cell_kinds.NAME] table may hold; which apply depends on its shape and body.
const std::vector<std::string_view> cell_kind_keys{
    "shape", "body", "diameter_um", "length_um", "width_um", "thickness_um", "arc_radius_um",
    "shell_thickness_um", "resolution", "mesh_size_um", "shear_modulus_Pa", "membrane_shear_modulus_pN_um",
    "bulk_modulus_Pa", "poisson_ratio", "density_kg_m3", "morse_well_depth_factor", "strain_hardening_ratio",
    "area_modulus_pN_um", "volume_modulus_Pa"};
// The keys that apply to a shell body only.
const std::vector<std::string_view> shell_body_keys{"shell_thickness_um", "membrane_shear_modulus_pN_um"};

constexpr std::array<CellShape, 3> all_cell_shapes{CellShape::rbc, CellShape::sickle, CellShape::sphere};

// The size keys of each shape.
std::vector<std::string_view> size_keys_of(CellShape shape) {
  switch (shape) {
    case CellShape::rbc:
    case CellShape::sphere: return {"diameter_um"};
    case CellShape::sickle: return {"length_um", "width_um", "thickness_um", "arc_radius_um"};
  }
  return {};
}

// Rejects size keys of another shape and shell keys on a filled body.
void check_keys_apply_to_shape_and_body(const TableReader& reader, const CellKindConfig& kind) {
  const std::vector<std::string_view> own_size_keys = size_keys_of(kind.shape);
  for (const std::string& key : reader.present_keys()) {
    const bool size_key = std::any_of(all_cell_shapes.begin(), all_cell_shapes.end(),
                                      [&](CellShape shape) { return contains(size_keys_of(shape), key); });
    if (size_key && !contains(own_size_keys, key))
      reader.fail(key, "does not belong to shape \"" + std::string(toml_name(kind.shape)) + "\" (its size keys are " +
                           joined(own_size_keys, false) + ")");
    if (kind.body == CellBody::filled && contains(shell_body_keys, key))
      reader.fail(key, std::string("applies to body = \"shell\" only, and this kind's body is \"filled\"") +
                           (key == "membrane_shear_modulus_pN_um" ? " (give shear_modulus_Pa)" : ""));
  }
}

// Fails when the file gives both of two keys that set the same quantity.
void check_not_both(const TableReader& reader, std::string_view first, std::string_view second) {
  if (reader.has(first) && reader.has(second))
    reader.fail(second, "give either " + std::string(first) + " or " + std::string(second) + ", not both");
}

// Shear modulus G [Pa] from shear_modulus_Pa or membrane_shear_modulus_pN_um (G = G_s / h),
// bulk modulus K [Pa] from bulk_modulus_Pa or poisson_ratio. K follows G through ν unless
// bulk_modulus_Pa is given; then ν is the one K and G imply.
void read_cell_moduli(const TableReader& reader, CellKindConfig& kind) {
  check_not_both(reader, "shear_modulus_Pa", "membrane_shear_modulus_pN_um");
  check_not_both(reader, "bulk_modulus_Pa", "poisson_ratio");
  const Range positive = Range::above(0);
  assign(kind.shear_modulus, reader.number("shear_modulus_Pa", positive));
  if (const auto membrane_shear_modulus = reader.number("membrane_shear_modulus_pN_um", positive))
    kind.shear_modulus = *membrane_shear_modulus / kind.shell_thickness;  // [pN/μm / μm = Pa]
  if (const auto bulk_modulus = reader.number("bulk_modulus_Pa", positive)) {
    kind.bulk_modulus = *bulk_modulus;
    kind.poisson_ratio = poisson_from_bulk_modulus(kind.shear_modulus, kind.bulk_modulus);
  } else {
    assign(kind.poisson_ratio, reader.number("poisson_ratio", Range::open(-1, 0.5)));
    kind.bulk_modulus = bulk_modulus_from_poisson(kind.shear_modulus, kind.poisson_ratio);
  }
}

// The smallest half-dimension of a body [μm] (a shell must be thinner) and what it is.
struct HalfDimension {
  double value;
  std::string what;
};
HalfDimension smallest_half_dimension(const CellKindConfig& kind) {
  switch (kind.shape) {
    case CellShape::rbc: {
      const double centre_thickness = rbc_centre_thickness_per_diameter * kind.diameter;
      return {0.5 * centre_thickness, "half the disc's thickness on its axis (" +
                                          format_number(rbc_centre_thickness_per_diameter) +
                                          " × diameter_um = " + format_number(centre_thickness) + " μm)"};
    }
    case CellShape::sphere: return {0.5 * kind.diameter, "the radius (diameter_um / 2)"};
    case CellShape::sickle: {
      HalfDimension smallest{0.5 * kind.length, "length_um / 2"};
      if (0.5 * kind.width < smallest.value) smallest = {0.5 * kind.width, "width_um / 2"};
      if (0.5 * kind.thickness < smallest.value) smallest = {0.5 * kind.thickness, "thickness_um / 2"};
      return smallest;
    }
  }
  return {0.0, "?"};
}

// Checks that the sizes of a kind make a body: a sickle's arc wider than its half-width,
// a shell thinner than the body's smallest half-dimension.
void check_cell_body(const TableReader& reader, const CellKindConfig& kind) {
  if (kind.shape == CellShape::sickle && !(kind.arc_radius > 0.5 * kind.width))
    reader.fail("arc_radius_um", "must be > width_um / 2 = " + format_number(0.5 * kind.width) +
                                     " μm (else the crescent's inner edge crosses its centre of curvature), got " +
                                     format_number(kind.arc_radius));
  if (kind.body != CellBody::shell) return;
  const HalfDimension limit = smallest_half_dimension(kind);
  if (!(kind.shell_thickness < limit.value))
    reader.fail("shell_thickness_um", "must be < " + format_number(limit.value) + " μm, " + limit.what + ", got " +
                                          format_number(kind.shell_thickness));
}

// One [cell_kinds.NAME] table, applied over `kind` (the built-in kind or the starting values).
void read_cell_kind(const TableReader& reader, CellKindConfig& kind) {
  assign(kind.shape, reader.choice("shape", choices_of({CellShape::rbc, CellShape::sickle, CellShape::sphere})));
  assign(kind.body, reader.choice("body", choices_of({CellBody::shell, CellBody::filled})));
  check_keys_apply_to_shape_and_body(reader, kind);
  const Range length = Range::above(0);
  assign(kind.diameter, reader.number("diameter_um", length));
  assign(kind.length, reader.number("length_um", length));
  assign(kind.width, reader.number("width_um", length));
  assign(kind.thickness, reader.number("thickness_um", length));
  assign(kind.arc_radius, reader.number("arc_radius_um", length));
  assign(kind.shell_thickness, reader.number("shell_thickness_um", length));
  assign(kind.resolution,
         reader.choice("resolution", choices_of({MeshResolution::coarse, MeshResolution::paper, MeshResolution::fine})));
  assign(kind.mesh_size, reader.number("mesh_size_um", Range::at_least(0)));
  read_cell_moduli(reader, kind);
  assign(kind.density, read_density(reader));
  assign(kind.morse_well_depth_factor, reader.number("morse_well_depth_factor", Range::at_least(0)));
  assign(kind.strain_hardening_ratio, reader.number("strain_hardening_ratio", Range::at_least(0)));
  assign(kind.area_modulus, reader.number("area_modulus_pN_um", Range::at_least(0)));
  assign(kind.volume_modulus, reader.number("volume_modulus_Pa", Range::at_least(0)));
  check_cell_body(reader, kind);
}

// [cell_kinds.NAME]: the built-in kinds, changed by tables of their name, then the kinds
// the file adds (in name order), each starting from the built-in "normal" cell.
void read_cell_kinds(const TableReader& root, std::vector<CellKindConfig>& kinds) {
  kinds = builtin_cell_kinds();
  const CellKindConfig builtin_normal = kinds.front();
  const TableReader section = root.table_of_names("cell_kinds");
  for (const std::string& name : section.present_keys()) {
    if (!is_bare_toml_key(name)) section.fail(name, "a cell kind's name is letters, digits, '_' and '-'");
    const auto builtin = std::find_if(kinds.begin(), kinds.end(), [&](const CellKindConfig& kind) { return kind.name == name; });
    CellKindConfig kind = builtin != kinds.end() ? *builtin : builtin_normal;
    kind.name = name;
    read_cell_kind(section.table(name, cell_kind_keys), kind);
    if (builtin != kinds.end()) *builtin = kind;
    else kinds.push_back(kind);
  }
}

// [[cells]]: the cells placed in the domain (placement itself is checked in src/geometry).
void read_cells(const TableReader& root, CaseConfig& config) {
  std::vector<std::pair<std::string_view, std::string>> kind_names;
  for (const CellKindConfig& kind : config.cell_kinds) kind_names.emplace_back(kind.name, kind.name);
  for (const TableReader& entry : root.array_of_tables("cells", {"kind", "center_um", "orientation_deg"})) {
    CellPlacement cell;
    assign(cell.kind, entry.choice("kind", kind_names));
    cell.center = require(entry, "center_um", entry.number3("center_um"));
    assign(cell.orientation, entry.number3("orientation_deg"));
    config.cells.push_back(cell);
  }
}

// ---- cell–cell interaction

const std::vector<std::string_view> morse_keys{"well_depth_pN_um3", "beta_per_um", "zero_force_length_um",
                                               "cutoff_um"};

// The Morse keys of `reader` over `morse`; β must exceed ln 2 / r0 (flat faces then balance
// at a positive gap, DESIGN.md) and the cut-off r0.
void read_morse(const TableReader& reader, MorseConfig& morse) {
  assign(morse.well_depth, reader.number("well_depth_pN_um3", Range::at_least(0)));
  assign(morse.beta, reader.number("beta_per_um", Range::above(0)));
  assign(morse.zero_force_length, reader.number("zero_force_length_um", Range::above(0)));
  assign(morse.cutoff, reader.number("cutoff_um", Range::above(0)));
  const double least_beta = std::log(2.0) / morse.zero_force_length;
  if (!(morse.beta > least_beta))
    reader.fail(reader.has("beta_per_um") ? "beta_per_um" : "zero_force_length_um",
                "β must be > ln 2 / r0 = " + format_number(least_beta) + " /μm (else flat faces pull into contact); got β = " +
                    format_number(morse.beta) + " /μm, r0 = " + format_number(morse.zero_force_length) + " μm");
  if (!(morse.cutoff > morse.zero_force_length))
    reader.fail("cutoff_um", "must be > zero_force_length_um (" + format_number(morse.zero_force_length) + "), got " +
                                 format_number(morse.cutoff));
}

void read_interaction(const TableReader& root, CaseConfig& config) {
  std::vector<std::string_view> keys{"enabled", "quadrature", "strength_multiplier", "skin_um", "pair"};
  keys.insert(keys.end(), morse_keys.begin(), morse_keys.end());
  const TableReader section = root.table("interaction", keys);
  InteractionConfig& interaction = config.interaction;
  assign(interaction.enabled, section.boolean("enabled"));
  assign(interaction.quadrature,
         section.choice("quadrature", choices_of({InteractionQuadrature::automatic, InteractionQuadrature::nodes,
                                                  InteractionQuadrature::gauss3, InteractionQuadrature::gauss6})));
  assign(interaction.strength, section.number("strength_multiplier", Range::at_least(0)));
  assign(interaction.skin, section.number("skin_um", Range::above(0)));
  read_morse(section, interaction.morse);
  std::vector<std::pair<std::string_view, std::string>> kind_names;
  for (const CellKindConfig& kind : config.cell_kinds) kind_names.emplace_back(kind.name, kind.name);
  std::vector<std::string_view> pair_keys{"kind_a", "kind_b"};
  pair_keys.insert(pair_keys.end(), morse_keys.begin(), morse_keys.end());
  for (const TableReader& entry : section.array_of_tables("pair", pair_keys)) {
    MorsePairConfig pair;
    pair.kind_a = require(entry, "kind_a", entry.choice("kind_a", kind_names));
    pair.kind_b = require(entry, "kind_b", entry.choice("kind_b", kind_names));
    pair.morse = interaction.morse;
    read_morse(entry, pair.morse);
    for (const MorsePairConfig& other : interaction.pairs)
      if ((other.kind_a == pair.kind_a && other.kind_b == pair.kind_b) ||
          (other.kind_a == pair.kind_b && other.kind_b == pair.kind_a))
        entry.fail("kind_b", "the pair " + pair.kind_a + "–" + pair.kind_b + " is given twice");
    interaction.pairs.push_back(pair);
  }
  if (interaction.enabled && config.cells.empty())
    section.fail("enabled", "the interaction acts between cells, and the case has no [[cells]]");
}

// ---- the coupling and the scene

void read_coupling(const TableReader& root, CouplingConfig& coupling) {
  const TableReader section = root.table(
      "coupling", {"scheme", "support_elements", "stable_step_factor", "allow_unstable_step", "gravity_m_s2",
                  "volume_tolerance", "forces_in_stabilization", "subscale_velocity"});
  assign(coupling.scheme, section.choice("scheme", choices_of({CouplingScheme::explicit_forces,
                                                               CouplingScheme::semi_implicit})));
  // Below one element a point's support may hold too few fluid nodes for the moment matrix.
  assign(coupling.support_elements, section.number("support_elements", Range::closed(1.0, 8.0)));
  assign(coupling.stable_step_factor, section.number("stable_step_factor", Range::above(0)));
  assign(coupling.allow_unstable_step, section.boolean("allow_unstable_step"));
  assign(coupling.forces_in_stabilization, section.boolean("forces_in_stabilization"));
  assign(coupling.subscale_velocity, section.boolean("subscale_velocity"));
  assign(coupling.volume_tolerance, section.number("volume_tolerance", Range::open(0, 1)));
  // With the loads in the stabilization, u' = −τ (r − f_h) holds τ f_h: the cells would
  // move with their own forces times a mobility the semi-implicit step does not linearize,
  // explicitly in the stiffest force (the capillary's capsule: +2.8 % volume in 10 steps of
  // 5e-4 s, diverged at step 12).
  if (coupling.forces_in_stabilization && coupling.subscale_velocity &&
      coupling.scheme == CouplingScheme::semi_implicit)
    section.fail("forces_in_stabilization",
                 "cannot be combined with subscale_velocity under scheme = \"semi_implicit\": the subscale velocity "
                 "then carries the cells' own forces, which the semi-implicit step does not linearize (use one of "
                 "the two, or scheme = \"explicit\")");
  if (const auto gravity = section.number3("gravity_m_s2"))
    for (int d = 0; d < 3; ++d) coupling.gravity[d] = (*gravity)[d] * 1e6;  // m/s² → μm/s²
}

void read_scene(const TableReader& root, SceneConfig& scene) {
  const TableReader section = root.table("scene", {"skip_unneeded_stages"});
  assign(scene.skip_unneeded_stages, section.boolean("skip_unneeded_stages"));
}

// The explicit coupling refuses a step above its stable estimate unless asked to force it
// (the semi-implicit coupling is not bound by it).
void check_time_step(const CaseConfig& config) {
  if (config.coupling.scheme == CouplingScheme::semi_implicit) return;
  const DerivedQuantities derived = derive_quantities(config);
  if (derived.stable_dt <= 0.0 || config.time.dt <= derived.stable_dt || config.coupling.allow_unstable_step) return;
  throw InputError(config.source_file, "time.dt_s",
                   format_number(config.time.dt) + " s exceeds the explicit coupling's stable step " +
                       format_number(derived.stable_dt) + " s (" + derived.stable_dt_reason +
                       "); lower time.dt_s, or set coupling.allow_unstable_step = true to run it anyway");
}

}  // namespace

bool is_bare_toml_key(std::string_view key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-';
  });
}

const char* toml_name(BoundaryType type) {
  switch (type) {
    case BoundaryType::periodic: return "periodic";
    case BoundaryType::wall: return "wall";
    case BoundaryType::inflow: return "inflow";
    case BoundaryType::traction: return "traction";
  }
  return "?";
}
const char* toml_name(InteractionQuadrature quadrature) {
  switch (quadrature) {
    case InteractionQuadrature::automatic: return "auto";
    case InteractionQuadrature::nodes: return "nodes";
    case InteractionQuadrature::gauss3: return "gauss3";
    case InteractionQuadrature::gauss6: return "gauss6";
  }
  return "?";
}
const char* toml_name(InflowProfile profile) {
  return profile == InflowProfile::uniform ? "uniform" : "parabolic";
}
const char* toml_name(TimeMode mode) { return mode == TimeMode::steady ? "steady" : "transient"; }
const char* toml_name(CouplingScheme scheme) {
  return scheme == CouplingScheme::semi_implicit ? "semi_implicit" : "explicit";
}

const char* toml_name(TimeScheme scheme) { return scheme == TimeScheme::bdf2 ? "bdf2" : "backward_euler"; }
const char* toml_name(StokesChoice choice) {
  switch (choice) {
    case StokesChoice::automatic: return "auto";
    case StokesChoice::on: return "on";
    case StokesChoice::off: return "off";
  }
  return "?";
}
const char* toml_name(PreconditionerType type) {
  switch (type) {
    case PreconditionerType::ilu0: return "ilu0";
    case PreconditionerType::block_jacobi: return "block_jacobi";
    case PreconditionerType::multigrid: return "multigrid";
    case PreconditionerType::none: break;
  }
  return "none";
}
const char* toml_name(CellShape shape) {
  switch (shape) {
    case CellShape::rbc: return "rbc";
    case CellShape::sickle: return "sickle";
    case CellShape::sphere: return "sphere";
  }
  return "?";
}
const char* toml_name(VesselTransition transition) {
  return transition == VesselTransition::cosine ? "cosine" : "cone";
}
const char* toml_name(CellBody body) { return body == CellBody::shell ? "shell" : "filled"; }
const char* toml_name(MeshResolution resolution) {
  switch (resolution) {
    case MeshResolution::coarse: return "coarse";
    case MeshResolution::paper: return "paper";
    case MeshResolution::fine: return "fine";
  }
  return "?";
}

namespace {

// The case in `document` (parsed from `path`), with the overrides applied, validated.
CaseConfig load_case_document(toml::table document, const std::string& path, const std::vector<std::string>& overrides) {
  const ErrorSource errors(path, apply_overrides(document, overrides));
  // [derived] is written by resolved_case_toml() for the reader; it is output-only.
  const TableReader root(&document, "", errors,
                         {"case", "fluid", "domain", "vessel", "boundary", "time", "solver", "scales", "output", "checkpoint",
                          "cell_kinds", "cells", "interaction", "coupling", "scene", "derived"});
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
  read_coupling(root, config.coupling);
  read_scene(root, config.scene);
  // The cells against the domain and each other (exact shapes, before any meshing).
  check_cell_placement(config);
  check_time_step(config);
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
