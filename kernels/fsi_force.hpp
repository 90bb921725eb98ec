#pragma once
// The fluid–structure interaction force at the cell nodes (paper eq. 7), lumped:
//   F_I = f_I^elastic + f_I^Morse + f_I^wall + m_I (g − (v_I^n − v_I^{n−1}) / Δt),
// with m_I = (ρ_s − ρ_f) V_I the node's excess mass (V_I: a quarter of the reference
// volume of each tetrahedron at I). With viscosity ratio 1, ∇·σ_s − ∇·σ_f reduces to the
// elastic force (docs/method.md, "The coupling"). Missing stages pass empty Views.
#include <Kokkos_Core.hpp>

namespace rouleau {

template <class NodeVectors, class Scalars>
struct FsiForceFunctor {
  using Inputs = typename NodeVectors::const_type;
  Inputs elastic;                      // f^elastic [pN]
  Inputs interaction;                  // f^Morse [pN], or empty
  Inputs wall;                         // f^wall, the vessel wall's repulsion [pN], or empty
  Scalars excess_mass;                 // m_I [pN·s²/μm], or empty
  Inputs velocity, previous_velocity;  // v^n, v^{n−1} [μm/s]
  double gravity[3];                   // [μm/s²]
  double inverse_dt;                   // 1/Δt of the last step [1/s], 0 before the first
  NodeVectors force;                   // F [pN]

  KOKKOS_INLINE_FUNCTION void operator()(const int node) const {
    const bool with_interaction = interaction.extent(0) > 0;
    const bool with_wall = wall.extent(0) > 0;
    const bool with_inertia = excess_mass.extent(0) > 0;
    for (int c = 0; c < 3; ++c) {
      double f = elastic(node, c);
      if (with_interaction) f += interaction(node, c);
      if (with_wall) f += wall(node, c);
      if (with_inertia) {
        const double acceleration = (velocity(node, c) - previous_velocity(node, c)) * inverse_dt;
        f += excess_mass(node) * (gravity[c] - acceleration);
      }
      force(node, c) = f;
    }
  }
};

}  // namespace rouleau
