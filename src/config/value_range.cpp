#include "config/value_range.hpp"

#include <cmath>

#include "util/number_text.hpp"

namespace rouleau {

bool Range::contains(double value) const {
  const bool above_lower = lower_inclusive ? value >= lower : value > lower;
  const bool below_upper = upper_inclusive ? value <= upper : value < upper;
  return above_lower && below_upper;
}

std::string Range::describe() const {
  std::string text;
  if (std::isfinite(lower)) text += (lower_inclusive ? "≥ " : "> ") + format_number(lower);
  if (std::isfinite(upper)) {
    if (!text.empty()) text += " and ";
    text += (upper_inclusive ? "≤ " : "< ") + format_number(upper);
  }
  return text;
}

}  // namespace rouleau
