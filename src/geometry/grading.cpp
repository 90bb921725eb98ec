#include "geometry/grading.hpp"

#include <algorithm>
#include <cmath>

namespace rouleau {

std::vector<double> graded_coordinates(double lower, double upper, int elements, double grading) {
  // Element sizes h_i ∝ q^min(i, n−1−i) with q^((n−1)/2) = grading.
  std::vector<double> sizes(elements, 1.0);
  if (grading != 1.0 && elements > 2) {
    const double q = std::pow(grading, 2.0 / (elements - 1));
    for (int i = 0; i < elements; ++i) sizes[i] = std::pow(q, std::min(i, elements - 1 - i));
  }
  double total = 0.0;
  for (double s : sizes) total += s;
  std::vector<double> x(elements + 1);
  x[0] = lower;
  double running = 0.0;
  for (int i = 0; i < elements; ++i) {
    running += sizes[i];
    x[i + 1] = lower + (upper - lower) * running / total;
  }
  x[elements] = upper;
  return x;
}

double smallest_graded_interval(double lower, double upper, int elements, double grading) {
  const std::vector<double> x = graded_coordinates(lower, upper, elements, grading);
  double smallest = upper - lower;
  for (int i = 0; i < elements; ++i) smallest = std::min(smallest, x[i + 1] - x[i]);
  return smallest;
}

}  // namespace rouleau
