#include "config/toml_table_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "config/case_overrides.hpp"
#include "util/number_text.hpp"
#include "util/errors.hpp"
#include "util/constants.hpp"

namespace rouleau {
namespace {

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

const toml::table& empty_table() {
  static const toml::table empty;
  return empty;
}

}  // namespace

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

std::string suggestion(std::string_view given, const std::vector<std::string_view>& candidates) {
  std::string_view best;
  std::size_t best_distance = 3;
  for (const auto candidate : candidates) {
    const std::size_t distance = edit_distance(given, candidate);
    if (distance < best_distance) best = candidate, best_distance = distance;
  }
  return best.empty() ? std::string() : "; did you mean \"" + std::string(best) + "\"?";
}

std::string joined(const std::vector<std::string_view>& names, bool quoted) {
  const std::string quote = quoted ? "\"" : "";
  std::string text;
  for (const auto name : names) text += (text.empty() ? "" : ", ") + quote + std::string(name) + quote;
  return text;
}

bool is_bare_toml_key(std::string_view key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-';
  });
}

// ---- ErrorSource

ErrorSource::ErrorSource(std::string file, std::vector<std::string> overridden_keys)
    : file_(std::move(file)), overridden_keys_(std::move(overridden_keys)) {}

void ErrorSource::fail(const std::string& key, const std::string& reason) const {
  throw InputError(file_for(key), key, reason);
}

std::string ErrorSource::file_for(const std::string& key) const {
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

// ---- TableReader: tables

TableReader::TableReader(const toml::table& document, const ErrorSource& errors,
                         std::vector<std::string_view> table_names)
    : TableReader(&document, "", "", errors, std::move(table_names)) {}

TableReader::TableReader(const toml::table* table, std::string path, std::string section, const ErrorSource& errors,
                         std::vector<std::string_view> allowed_keys)
    : table_(table ? table : &empty_table()), path_(std::move(path)), section_(std::move(section)), errors_(errors),
      allowed_keys_(std::move(allowed_keys)) {
  for (const auto& [key, node] : *table_) {
    const std::string_view name = key.str();
    if (std::find(allowed_keys_.begin(), allowed_keys_.end(), name) != allowed_keys_.end()) continue;
    fail(name, std::string(node.is_table() ? "unknown table" : "unknown key") + suggestion(name, allowed_keys_));
  }
}

std::string TableReader::path_of(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void TableReader::fail(std::string_view key, const std::string& reason) const { errors_.fail(path_of(key), reason); }

std::vector<std::string> TableReader::present_keys() const {
  std::vector<std::string> keys;
  for (const auto& [key, node] : *table_) keys.emplace_back(key.str());
  return keys;
}

bool TableReader::has(std::string_view key) const { return node(key) != nullptr; }

TableReader TableReader::table(std::string_view key, std::string_view section) const {
  const std::string section_name = section.empty() ? path_of(key) : std::string(section);
  // A table's allowed keys: its own, then the arrays of tables under it ([[interaction.pair]]).
  std::vector<std::string_view> allowed = case_key_names(section_name);
  for (const CaseSection& sub : case_sections())
    if (sub.name.size() > section_name.size() + 1 && sub.name.compare(0, section_name.size() + 1, section_name + ".") == 0)
      allowed.push_back(sub.name.substr(section_name.size() + 1));
  const toml::node* found = node(key);
  if (found && !found->is_table()) expected(key, "a table", *found);
  return TableReader(found ? found->as_table() : nullptr, path_of(key), section_name, errors_, std::move(allowed));
}

TableReader TableReader::table_of_tables(std::string_view key, std::vector<std::string_view> table_names) const {
  const toml::node* found = node(key);
  if (found && !found->is_table()) expected(key, "a table", *found);
  return TableReader(found ? found->as_table() : nullptr, path_of(key), path_of(key), errors_, std::move(table_names));
}

TableReader TableReader::table_of_names(std::string_view key) const {
  const toml::node* found = node(key);
  if (found && !found->is_table()) expected(key, "a table", *found);
  std::vector<std::string_view> names;
  if (found)
    for (const auto& [name, value] : *found->as_table()) names.push_back(name.str());
  return TableReader(found ? found->as_table() : nullptr, path_of(key), path_of(key), errors_, std::move(names));
}

std::vector<TableReader> TableReader::array_of_tables(std::string_view key) const {
  const toml::node* found = node(key);
  if (!found) return {};
  const std::string what = "an array of tables ([[" + path_of(key) + "]] entries)";
  if (!found->is_array()) expected(key, what, *found);
  const std::string section_name = path_of(key);
  const std::vector<std::string_view> allowed = case_key_names(section_name);
  const toml::array& elements = *found->as_array();
  std::vector<TableReader> entries;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const std::string entry_key = std::string(key) + "[" + std::to_string(i) + "]";
    if (!elements.get(i)->is_table()) expected(entry_key, "a table (an entry of " + what + ")", *elements.get(i));
    entries.push_back(TableReader(elements.get(i)->as_table(), path_of(entry_key), section_name, errors_, allowed));
  }
  return entries;
}

// ---- TableReader: values

std::optional<double> TableReader::number(std::string_view key) const {
  const toml::node* found = value_node(key, ValueKind::number);
  if (!found) return std::nullopt;
  const double value = number_value(key, *found, "");
  check_range(key, value, "");
  return value;
}

std::optional<int> TableReader::integer(std::string_view key) const {
  const toml::node* found = value_node(key, ValueKind::integer);
  if (!found) return std::nullopt;
  const std::int64_t value = integer_value(key, *found, "");
  check_range(key, value, "");
  return static_cast<int>(value);
}

std::optional<bool> TableReader::boolean(std::string_view key) const {
  const toml::node* found = value_node(key, ValueKind::boolean);
  if (!found) return std::nullopt;
  if (!found->is_boolean()) expected(key, "a boolean (true or false)", *found);
  return found->as_boolean()->get();
}

std::optional<std::string> TableReader::text(std::string_view key) const {
  const toml::node* found = value_node(key, ValueKind::text);
  if (!found) return std::nullopt;
  if (!found->is_string()) expected(key, "a string", *found);
  return found->as_string()->get();
}

std::optional<std::array<double, 3>> TableReader::number3(std::string_view key) const {
  return triple<double>(key, ValueKind::number3, "numbers", [&](const toml::node& element, const std::string& label) {
    return number_value(key, element, label);
  });
}

std::optional<std::array<std::int64_t, 3>> TableReader::integer3(std::string_view key) const {
  return triple<std::int64_t>(key, ValueKind::integer3, "integers",
                              [&](const toml::node& element, const std::string& label) {
                                return integer_value(key, element, label);
                              });
}

std::optional<std::string> TableReader::kind_name(std::string_view key,
                                                  const std::vector<std::string_view>& kind_names) const {
  return one_of(key, ValueKind::kind_name, kind_names);
}

std::optional<std::string> TableReader::one_of(std::string_view key, ValueKind kind,
                                               const std::vector<std::string_view>& names) const {
  const toml::node* found = value_node(key, kind);
  if (!found) return std::nullopt;
  if (!found->is_string()) expected(key, "a string", *found);
  const std::string name = found->as_string()->get();
  const std::vector<std::string_view>& allowed = names.empty() ? case_key(section_, key).choices : names;
  if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
    fail(key, "must be one of " + joined(allowed, true) + "; got \"" + name + "\"" + suggestion(name, allowed));
  return name;
}

const toml::node* TableReader::node(std::string_view key) const {
  if (std::find(allowed_keys_.begin(), allowed_keys_.end(), key) == allowed_keys_.end())
    throw std::logic_error("rouleau::load_case: reading undeclared key " + path_of(key));
  return table_->get(key);
}

const toml::node* TableReader::value_node(std::string_view key, ValueKind kind) const {
  if (case_key(section_, key).kind != kind)
    throw std::logic_error("rouleau::load_case: " + path_of(key) + " read as another type than the key table's");
  return node(key);
}

const Range& TableReader::range_of(std::string_view key) const { return case_key(section_, key).range; }

void TableReader::expected(std::string_view key, const std::string& what, const toml::node& found,
                           const std::string& label) const {
  fail(key, label + "expected " + what + ", got " + type_phrase(found.type()));
}

double TableReader::number_value(std::string_view key, const toml::node& found, const std::string& label) const {
  if (found.is_integer()) return static_cast<double>(found.as_integer()->get());
  if (!found.is_floating_point()) expected(key, "a number", found, label);
  const double value = found.as_floating_point()->get();
  if (!std::isfinite(value)) fail(key, label + "must be a finite number, got " + format_number(value));
  return value;
}

std::int64_t TableReader::integer_value(std::string_view key, const toml::node& found, const std::string& label) const {
  if (!found.is_integer()) expected(key, "an integer", found, label);
  const std::int64_t value = found.as_integer()->get();
  if (value > std::numeric_limits<int>::max() || value < std::numeric_limits<int>::min())
    fail(key, label + "out of the range of a 32-bit integer, got " + format_number(value));
  return value;
}

void TableReader::check_range(std::string_view key, double value, const std::string& label) const {
  const Range& range = range_of(key);
  if (!range.contains(value)) fail(key, label + "must be " + range.describe() + ", got " + format_number(value));
}

void TableReader::check_range(std::string_view key, std::int64_t value, const std::string& label) const {
  const Range& range = range_of(key);
  if (!range.contains(static_cast<double>(value)))
    fail(key, label + "must be " + range.describe() + ", got " + format_number(value));
}

template <class Number, class ReadElement>
std::optional<std::array<Number, 3>> TableReader::triple(std::string_view key, ValueKind kind,
                                                         const std::string& element_kind,
                                                         ReadElement read_element) const {
  const toml::node* found = value_node(key, kind);
  if (!found) return std::nullopt;
  const std::string what = "an array of 3 " + element_kind;
  if (!found->is_array()) expected(key, what, *found);
  const toml::array& elements = *found->as_array();
  if (elements.size() != 3) fail(key, "expected " + what + ", got " + std::to_string(elements.size()) + " elements");
  std::array<Number, 3> values{};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string label = "component " + std::string(axis_names[i]) + ": ";
    values[i] = read_element(*elements.get(i), label);
    check_range(key, values[i], label);
  }
  return values;
}

}  // namespace rouleau
