#include "analysis/paper_measure.hpp"

#include <cstdio>
#include <stdexcept>

namespace rouleau {

std::string PaperMeasure::text() const {
  char line[256];
  std::snprintf(line, sizeof(line), "%s %.4f %s %.4g%s%s: %s", metric.c_str(), value, relation.c_str(), threshold,
                unit.empty() ? "" : " ", unit.c_str(), met ? "yes" : "NO");
  return line;
}

PaperMeasure measure_against(const std::string& metric, double value, const std::string& relation, double threshold,
                             const std::string& unit) {
  PaperMeasure measure{metric, unit, value, relation, threshold, false};
  if (relation == "<")
    measure.met = value < threshold;
  else if (relation == "<=")
    measure.met = value <= threshold;
  else if (relation == ">")
    measure.met = value > threshold;
  else if (relation == ">=")
    measure.met = value >= threshold;
  else
    throw std::invalid_argument("rouleau::measure_against: relation must be <, <=, > or >=, got \"" + relation + "\"");
  return measure;
}

}  // namespace rouleau
