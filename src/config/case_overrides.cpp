#include "config/case_overrides.hpp"

#include <algorithm>
#include <string_view>

#include "config/toml_table_reader.hpp"
#include "util/errors.hpp"

namespace rouleau {
namespace {

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

}  // namespace

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

}  // namespace rouleau
