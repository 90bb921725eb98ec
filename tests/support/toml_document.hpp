#pragma once
// A parsed TOML document for tests that compare case-file values, behind an interface with
// no toml++ type: toml++'s headers do not pass through nvcc, so this is compiled with the
// host compiler (tests/CMakeLists.txt) and the tests that use it need not include them.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace rouleau::testing {

class TomlDocument {
 public:
  // Throws std::runtime_error when `text` is not TOML.
  explicit TomlDocument(const std::string& text);
  ~TomlDocument();
  TomlDocument(TomlDocument&&) noexcept;

  // The value at the dotted `path` ("fluid.density_kg_m3") as TOML text, or nothing.
  std::optional<std::string> value_text(const std::string& path) const;
  // Whether the value at `path` equals the TOML value `documented` ("0.0012", "[0, 0, 0]",
  // "\"wall\""), numbers to a relative 1e-5 (the 6 digits a table gives them with);
  // nothing when `documented` is not a TOML value ("required") or `path` holds none.
  std::optional<bool> equals(std::string_view documented, const std::string& path) const;

 private:
  struct Parsed;
  std::unique_ptr<Parsed> parsed_;
};

}  // namespace rouleau::testing
