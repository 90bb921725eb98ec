#pragma once
// One measure of one of the paper's statements, held to its threshold: what a scene's check
// (scene_checks.hpp) compares, in a form that prints as a line and writes as a CSV row
// (paper_checks.hpp). Host-only.
#include <string>

namespace rouleau {

struct PaperMeasure {
  std::string metric;    // what is measured, in words: "largest gap growth"
  std::string unit;      // of value and threshold: "um", "deg", "" for a ratio
  double value = 0.0;
  std::string relation;  // "<", "<=", ">" or ">="
  double threshold = 0.0;
  bool met = false;      // value relation threshold

  // "largest gap growth 0.1234 < 0.25 um: yes" (NO when not met).
  std::string text() const;
};

// The measure `metric` = `value` held to `relation` `threshold`. Throws
// std::invalid_argument for a relation other than <, <=, >, >=.
PaperMeasure measure_against(const std::string& metric, double value, const std::string& relation, double threshold,
                             const std::string& unit);

}  // namespace rouleau
