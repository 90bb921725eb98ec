#pragma once
// The explicit move of the cell nodes with the velocity interpolated from the fluid
// (docs/method.md, "The coupling"): v_I^{n+1} = U v̂_I (v̂ interpolated from the scaled fluid
// state), x_I^{n+1} = x_I^n + Δt v_I^{n+1}, keeping v_I^n for dv/dt. Reduces (with
// Kokkos::Max) the largest speed squared; a velocity that is NaN or Inf reduces to
// non_finite_speed2 and its node is not moved.
#include <Kokkos_Core.hpp>

namespace rouleau {

template <class NodeVectors>
struct MoveCellsFunctor {
  static constexpr double non_finite_speed2 = 1.7e308;

  typename NodeVectors::const_type scaled_velocity;  // v̂_I (in: interpolated from the scaled state)
  NodeVectors velocity;                              // v_I [μm/s] (in: v^n, out: v^{n+1})
  NodeVectors previous_velocity;                     // out: v_I^n [μm/s]
  NodeVectors position;                              // x_I [μm] (in/out)
  double velocity_scale;                             // U [μm/s]
  double dt;                                         // [s]

  KOKKOS_INLINE_FUNCTION void operator()(const int node, double& largest_speed2) const {
    double v[3], speed2 = 0.0;
    for (int c = 0; c < 3; ++c) {
      v[c] = velocity_scale * scaled_velocity(node, c);
      speed2 += v[c] * v[c];
    }
    // NaN fails every comparison; Inf exceeds the largest double
    if (!(speed2 < non_finite_speed2)) {
      largest_speed2 = non_finite_speed2;
      return;
    }
    for (int c = 0; c < 3; ++c) {
      previous_velocity(node, c) = velocity(node, c);
      velocity(node, c) = v[c];
      position(node, c) += dt * v[c];
    }
    if (speed2 > largest_speed2) largest_speed2 = speed2;
  }
};

}  // namespace rouleau
