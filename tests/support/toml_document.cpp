#include "support/toml_document.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <toml++/toml.h>

namespace rouleau::testing {

struct TomlDocument::Parsed {
  toml::table table;
};

namespace {
// Whether two TOML values are equal, numbers to a relative 1e-5.
bool same_value(const toml::node& documented, const toml::node& resolved) {
  if (documented.is_number() && resolved.is_number()) {
    const double a = documented.value<double>().value(), b = resolved.value<double>().value();
    return std::abs(a - b) <= 1e-5 * std::abs(b);
  }
  if (documented.is_array() && resolved.is_array()) {
    const toml::array &a = *documented.as_array(), &b = *resolved.as_array();
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!same_value(*a.get(i), *b.get(i))) return false;
    return true;
  }
  if (documented.is_string() && resolved.is_string()) return documented.value<std::string>() == resolved.value<std::string>();
  if (documented.is_boolean() && resolved.is_boolean()) return documented.value<bool>() == resolved.value<bool>();
  return false;
}
}  // namespace

TomlDocument::TomlDocument(const std::string& text) : parsed_(std::make_unique<Parsed>()) {
  try {
    parsed_->table = toml::parse(text);
  } catch (const toml::parse_error& error) {
    throw std::runtime_error(std::string("TomlDocument: ") + std::string(error.description()));
  }
}

TomlDocument::~TomlDocument() = default;
TomlDocument::TomlDocument(TomlDocument&&) noexcept = default;

std::optional<std::string> TomlDocument::value_text(const std::string& path) const {
  const toml::node* node = parsed_->table.at_path(path).node();
  if (!node) return std::nullopt;
  std::ostringstream text;
  node->visit([&](const auto& value) { text << value; });
  return text.str();
}

std::optional<bool> TomlDocument::equals(std::string_view documented, const std::string& path) const {
  toml::table value;
  try {
    value = toml::parse("value = " + std::string(documented));
  } catch (const toml::parse_error&) {
    return std::nullopt;  // "required", "radius_um", ...
  }
  const toml::node* resolved = parsed_->table.at_path(path).node();
  if (!resolved) return std::nullopt;
  return same_value(*value.get("value"), *resolved);
}

}  // namespace rouleau::testing
