#pragma once
// Node coordinates of a graded one-dimensional grid (box meshes refined toward walls).
// Host-only: includes no Kokkos header.
#include <vector>

namespace rouleau {

// Node coordinates along one direction: `elements` intervals on [lower, upper], sizes
// growing geometrically from both ends to the middle so that the largest is `grading`
// times the smallest (grading = 1: uniform).
std::vector<double> graded_coordinates(double lower, double upper, int elements, double grading);

// The smallest interval of graded_coordinates(lower, upper, elements, grading).
double smallest_graded_interval(double lower, double upper, int elements, double grading);

}  // namespace rouleau
