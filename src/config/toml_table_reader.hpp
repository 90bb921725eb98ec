#pragma once
// Typed reading of a case file's TOML tables: each table's allowed keys, and each key's
// type and range, come from the key table (case_keys.hpp); every fault is an InputError
// "file: dotted.key: reason" (the file is "--set" for a key a command-line override set).
// Host-only: includes no Kokkos header.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <vector>

#include "config/case_file_names.hpp"
#include "config/case_keys.hpp"

namespace rouleau {

// "a string", "an integer", ... for "expected X, got Y" messages.
std::string type_phrase(toml::node_type type);

// "; did you mean "X"?" for the closest of `candidates` within edit distance 2, else "".
std::string suggestion(std::string_view given, const std::vector<std::string_view>& candidates);

// The names separated by ", ", each in double quotes when `quoted`.
std::string joined(const std::vector<std::string_view>& names, bool quoted);

// Whether `key` can be written as a bare TOML key (letters, digits, '_' and '-'; not empty).
bool is_bare_toml_key(std::string_view key);

// Reports errors with the right "file": the case file, or "--set" for keys that came
// from a command-line override (or lie under / above one).
class ErrorSource {
 public:
  ErrorSource(std::string file, std::vector<std::string> overridden_keys);
  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;

 private:
  std::string file_for(const std::string& key) const;

  std::string file_;
  std::vector<std::string> overridden_keys_;
};

// One table of the case file, read as the key table's `section` (or, for a table that
// only holds other tables, with the names it may hold). The constructor rejects keys that
// are not allowed (suggesting the closest); the readers return typed values at the
// table's keys, checking type, array length and range, and report errors with the dotted
// key. A value read of a key the key table lacks, or of another type, is a programming
// error (std::logic_error).
class TableReader {
 public:
  // The whole document: its allowed keys are the top-level tables.
  TableReader(const toml::table& document, const ErrorSource& errors, std::vector<std::string_view> table_names);

  // The dotted key of `key` in this table.
  std::string path_of(std::string_view key) const;
  [[noreturn]] void fail(std::string_view key, const std::string& reason) const;
  // The keys present in the file, in file order.
  std::vector<std::string> present_keys() const;
  // Whether the file gives `key`.
  bool has(std::string_view key) const;

  // The sub-table `key`, read as the key table's section `section` (by default the
  // sub-table's own dotted name). An absent table reads as empty.
  TableReader table(std::string_view key, std::string_view section = {}) const;
  // The sub-table `key` that holds only the tables `table_names`.
  TableReader table_of_tables(std::string_view key, std::vector<std::string_view> table_names) const;
  // The sub-table `key` whose keys are names the file chooses (such as [cell_kinds.NAME]);
  // every key is allowed. An absent table reads as empty.
  TableReader table_of_names(std::string_view key) const;
  // The entries of an array of tables ([[key]]), each read as the section of that dotted
  // name with the dotted key "key[I]" (I from 0). An absent array reads as empty.
  std::vector<TableReader> array_of_tables(std::string_view key) const;

  // A finite number (integers accepted) in the key's range.
  std::optional<double> number(std::string_view key) const;
  // An integer in the key's range that fits an int.
  std::optional<int> integer(std::string_view key) const;
  std::optional<bool> boolean(std::string_view key) const;
  std::optional<std::string> text(std::string_view key) const;
  // An array of 3 finite numbers, each in the key's range.
  std::optional<std::array<double, 3>> number3(std::string_view key) const;
  // An array of 3 integers, each in the key's range.
  std::optional<std::array<std::int64_t, 3>> integer3(std::string_view key) const;
  // One of the key's choices, or of `only` (a part of them) when given.
  template <class Enum>
  std::optional<Enum> choice(std::string_view key, const std::vector<std::string_view>& only = {}) const {
    const std::optional<std::string> name = one_of(key, ValueKind::choice, only);
    if (!name) return std::nullopt;
    return enum_named<Enum>(*name);
  }
  // The name of a cell kind, one of `kind_names`.
  std::optional<std::string> kind_name(std::string_view key, const std::vector<std::string_view>& kind_names) const;

 private:
  TableReader(const toml::table* table, std::string path, std::string section, const ErrorSource& errors,
              std::vector<std::string_view> allowed_keys);

  const toml::node* node(std::string_view key) const;
  // The node of a value key, after checking that the key table has it with `kind`.
  const toml::node* value_node(std::string_view key, ValueKind kind) const;
  const Range& range_of(std::string_view key) const;
  std::optional<std::string> one_of(std::string_view key, ValueKind kind, const std::vector<std::string_view>& names) const;
  [[noreturn]] void expected(std::string_view key, const std::string& what, const toml::node& found,
                             const std::string& label = "") const;
  double number_value(std::string_view key, const toml::node& found, const std::string& label) const;
  std::int64_t integer_value(std::string_view key, const toml::node& found, const std::string& label) const;
  void check_range(std::string_view key, double value, const std::string& label) const;
  void check_range(std::string_view key, std::int64_t value, const std::string& label) const;
  template <class Number, class ReadElement>
  std::optional<std::array<Number, 3>> triple(std::string_view key, ValueKind kind, const std::string& element_kind,
                                              ReadElement read_element) const;

  const toml::table* table_;
  std::string path_;
  std::string section_;  // the key table's section this table is read as
  const ErrorSource& errors_;
  std::vector<std::string_view> allowed_keys_;
};

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
// The value of a required key; fails with "missing required key" when it was absent.
template <class Value>
Value require(const TableReader& table, std::string_view key, const std::optional<Value>& value) {
  if (!value) table.fail(key, "missing required key");
  return *value;
}

}  // namespace rouleau
