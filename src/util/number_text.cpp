#include "util/number_text.hpp"

#include <charconv>

namespace rouleau {
namespace {

// `value` by std::to_chars: the shortest round-trip text when `precision` < 0, else %g with
// that many significant digits.
std::string chars_of(double value, int precision) {
  char text[64];
  const auto result = precision < 0 ? std::to_chars(text, text + sizeof(text), value)
                                    : std::to_chars(text, text + sizeof(text), value, std::chars_format::general, precision);
  return std::string(text, result.ptr);
}

}  // namespace

std::string format_number(double value, int significant_digits) { return chars_of(value, significant_digits); }

std::string format_number(std::int64_t value) { return std::to_string(value); }

std::string toml_float(double value) {
  std::string written = chars_of(value, -1);
  if (written.find_first_of(".e") == std::string::npos) written += ".0";  // else TOML reads an integer
  return written;
}

}  // namespace rouleau
