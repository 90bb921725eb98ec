#pragma once
// The interval of values a number in a case file may take.
// Host-only: includes no Kokkos header.
#include <limits>
#include <string>

namespace rouleau {

// An allowed interval of values; describe() gives "> 0", "≥ 1 and ≤ 4096", ... ("" for any).
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

  bool contains(double value) const;
  std::string describe() const;
};

}  // namespace rouleau
