#include "config/case_file_reference.hpp"

#include <sstream>
#include <string_view>

#include "config/case_keys.hpp"

namespace rouleau {
namespace {

constexpr const char* introduction = R"(# Case-file reference

A case is a [TOML](https://toml.io) file. Every quantity with a unit carries it in its
key's name (`dt_s` in seconds, `viscosity_Pa_s` in Pa·s, `center_um` in μm); arrays of 3
are x, y, z. rouleau converts to its internal units (μm, s, pN) once, when it loads the
file.

Every key is checked before any work: an unknown key or table, a wrong type or array
length, a missing required key, a value out of range, or cells outside the domain or
overlapping each other stop the run with exit code 2 and one line on stderr naming the
file, the key and the reason:

```
rouleau: case.toml: fluid.viscosity_Pa_s: must be > 0, got -1
rouleau: case.toml: cell_kinds.normal.diametre_um: unknown key; did you mean "diameter_um"?
```

`rouleau run` and `rouleau check` take `--set KEY=VALUE` (repeatable) to change a key
without editing the file, as `--set time.dt_s=0.001 --set cell_kinds.normal.resolution=coarse`;
the value is read as TOML, or as a string when it is not one. Errors about such a key
name `--set` as the file. A run writes the resolved case (every key with the value it
used) into its output folder; it loads again as a case file.

Below, each table in the order of a case file, then its keys. "Allowed" is the range each
number (each component of an array) must lie in, or the choices.
)";

std::string allowed_values(const CaseKey& key) {
  const std::string range = key.range.describe();
  const std::string each = range.empty() ? "" : ", each " + range;
  switch (key.kind) {
    case ValueKind::number: return range.empty() ? "number" : range;
    case ValueKind::integer: return "integer" + (range.empty() ? "" : " " + range);
    case ValueKind::boolean: return "true, false";
    case ValueKind::text: return "string";
    case ValueKind::kind_name: return "a [cell_kinds] name";
    case ValueKind::number3: return "3 numbers" + each;
    case ValueKind::integer3: return "3 integers" + each;
    case ValueKind::choice: {
      std::string names;
      for (const std::string_view name : key.choices) names += (names.empty() ? "\"" : ", \"") + std::string(name) + "\"";
      return names;
    }
  }
  return "";
}

}  // namespace

std::string case_file_reference() {
  std::ostringstream page;
  page << introduction;
  for (const CaseSection& section : case_sections()) {
    page << "\n## " << section.header << "\n\n";
    if (!section.about.empty()) page << section.about << "\n\n";
    page << "| Key | Unit | Default | Allowed | Meaning |\n|---|---|---|---|---|\n";
    for (const CaseKey& key : case_keys())
      if (key.section == section.name)
        page << "| `" << key.name << "` | " << key.unit << " | " << key.default_value << " | " << allowed_values(key)
             << " | " << key.meaning << " |\n";
  }
  return page.str();
}

}  // namespace rouleau
