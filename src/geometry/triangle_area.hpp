#pragma once
// The area of a triangle given by its three corners (host code: meshes, flow-rate sections,
// surface quadrature).
#include <array>
#include <cmath>

namespace rouleau {

// |(b − a) × (c − a)| / 2
inline double triangle_area(const std::array<double, 3>& a, const std::array<double, 3>& b,
                            const std::array<double, 3>& c) {
  const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

}  // namespace rouleau
