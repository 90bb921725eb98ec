#pragma once
// The keys of a case file: for each, its table, type, unit, default, allowed range or
// choices and meaning. The loader reads every key through this table (TableReader takes
// a table's allowed keys, each key's type and its range from it), and the case-file
// reference (case_file_reference.hpp) is rendered from it, so neither can name a key the
// other does not.
// Host-only: includes no Kokkos header.
#include <string_view>
#include <vector>

#include "config/value_range.hpp"

namespace rouleau {

// What a key's value is in the file.
enum class ValueKind {
  number,     // a finite number (an integer is accepted)
  integer,    // an integer that fits 32 bits
  boolean,    // true or false
  text,       // a string
  choice,     // one of the key's choices (a string)
  kind_name,  // the name of a cell kind (a string)
  number3,    // an array of 3 numbers, x y z
  integer3,   // an array of 3 integers, x y z
};

// A table of the case file: `name` as the loader and the key table call it ("fluid",
// "boundary.SIDE", "cell_kinds.NAME", "cells", ...), its header in a file and what it holds.
struct CaseSection {
  std::string_view name;
  std::string_view header;  // "[fluid]", "[boundary.SIDE]", "[[cells]]", ...
  std::string_view about;
};

struct CaseKey {
  std::string_view section;  // a CaseSection name
  std::string_view name;
  ValueKind kind;
  std::string_view unit;           // "" when the value has none
  std::string_view default_value;  // as a reader of the reference needs it ("1025", "required", "radius_um")
  Range range;                     // numbers: each value (each component of an array)
  std::vector<std::string_view> choices;  // kind == choice: the spellings, in message order
  std::string_view meaning;
};

// The tables, in the order of a case file.
const std::vector<CaseSection>& case_sections();

// Every key, grouped by table in the order of case_sections().
const std::vector<CaseKey>& case_keys();

// The key `name` of `section`; throws std::logic_error when the table has no such key.
const CaseKey& case_key(std::string_view section, std::string_view name);

// The names of the keys of `section`, in table order.
std::vector<std::string_view> case_key_names(std::string_view section);

}  // namespace rouleau
