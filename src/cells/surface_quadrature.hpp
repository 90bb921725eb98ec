#pragma once
// Host-side setup data: where the cells' surface integrals (the Morse interaction, paper eq. 11) are sampled:
// at the surface nodes with their area weights (nodal quadrature), or at Gauss points of
// each surface triangle. A point p sits at x_p = Σ_k s_pk x_{n_pk} (up to three nodes n_pk
// with shape values s_pk) and carries the weight w_p (its share of the reference area);
// a force F_p on it goes to its nodes as s_pk F_p, so the nodal forces stay exactly minus
// the gradient of the discrete energy.
//
// Triangle rules (barycentric coordinates of the three vertices; weights sum to 1):
//   gauss3, degree 2: (2/3, 1/6, 1/6) and its permutations, weight 1/3 each;
//   gauss6, degree 4 (Dunavant 1985): (b, a, a) with a = 0.445948490915965,
//     b = 1 − 2a, weight 0.223381589678011, and (d, c, c) with c = 0.091576213509771,
//     d = 1 − 2c, weight 0.109951743655322, each with its permutations.
#include <array>
#include <cmath>
#include <vector>

#include "geometry/triangle_area.hpp"

namespace rouleau {

enum class SurfaceQuadrature { nodes, gauss3, gauss6 };

struct TrianglePoint {
  std::array<double, 3> barycentric;
  double weight;
};

// The rule's points (empty for nodal quadrature).
inline std::vector<TrianglePoint> triangle_rule(SurfaceQuadrature quadrature) {
  auto permutations = [](double first, double other, double weight) {
    return std::vector<TrianglePoint>{{{first, other, other}, weight},
                                      {{other, first, other}, weight},
                                      {{other, other, first}, weight}};
  };
  switch (quadrature) {
    case SurfaceQuadrature::nodes: return {};
    case SurfaceQuadrature::gauss3: return permutations(2.0 / 3.0, 1.0 / 6.0, 1.0 / 3.0);
    case SurfaceQuadrature::gauss6: {
      const double a = 0.445948490915965, c = 0.091576213509771;
      auto rule = permutations(1.0 - 2.0 * a, a, 0.223381589678011);
      const auto second = permutations(1.0 - 2.0 * c, c, 0.109951743655322);
      rule.insert(rule.end(), second.begin(), second.end());
      return rule;
    }
  }
  return {};
}

}  // namespace rouleau
