#pragma once
// The device kernels of the static equilibrium solve (src/cells/static_equilibrium.hpp):
// FIRE 2.0's residual, power and move in the mass-scaled variables y = √m x, u = √m v,
// g = r/√m (src/cells/fire_relaxation.cpp), the pull vector p = Σ_a w_a x_a
// (src/cells/equilibrium_forces.cpp), and the power iteration's finite-difference
// stiffness action (src/cells/stiffness_estimate.cpp); each sums three numbers over the
// nodes (reduce3).
#include <Kokkos_Core.hpp>
#include <array>

namespace rouleau {
namespace static_relaxation {

using ConstNodeVectors = Kokkos::View<const double* [3]>;
using NodeVectors = Kokkos::View<double* [3]>;

// The residual and FIRE's power, summed over the nodes (an array reduction: the default
// join adds, the default init zeroes, in Kokkos 3.4 and 4.x alike):
//   r_a = f_int,a + f_pressure,a + f_dead,a + F w_a p̂,   g_a = r_a / √m_a,
//   sums = {P = Σ u_a·g_a, Σ u_a·u_a, Σ g_a·g_a}.
struct ResidualPowerFunctor {
  using value_type = double[];
  unsigned value_count = 3;
  ConstNodeVectors internal_forces, constraint_forces, dead_loads, scaled_velocity;
  Kokkos::View<const double*> pull_weights, inverse_sqrt_mass;
  NodeVectors residual;
  double pull[3];  // F p̂ [pN]

  KOKKOS_INLINE_FUNCTION void operator()(const int a, value_type sums) const {
    const double w = pull_weights(a);
    for (int i = 0; i < 3; ++i) {
      const double r = internal_forces(a, i) + constraint_forces(a, i) + dead_loads(a, i) + w * pull[i];
      residual(a, i) = r;
      const double g = r * inverse_sqrt_mass(a);
      const double u = scaled_velocity(a, i);
      sums[0] += u * g;
      sums[1] += u * u;
      sums[2] += g * g;
    }
  }
};

// One FIRE 2.0 move in the mass-scaled variables (y = √m x, u = √m v, g = r/√m), per node:
//   if uphill:  x ← x − ½ Δt u/√m,  u ← 0            (step back, stop)
//   u ← u + Δt g                                     (semi-implicit Euler)
//   u ← (1 − α) u + (α |u|/|g|) g                     (mix toward the force; `mix` is
//                                                      α|u|/|g| with the global norms)
//   u ← s u                                          (s ≤ 1 caps the largest move)
//   x ← x + Δt u/√m
// and sums p = Σ_a w_a x_a at the new positions (the pull's direction).
struct FireMoveFunctor {
  using value_type = double[];
  unsigned value_count = 3;
  NodeVectors positions, scaled_velocity;
  ConstNodeVectors residual;
  Kokkos::View<const double*> pull_weights, inverse_sqrt_mass;
  bool uphill;
  double step, alpha, mix, scale;

  KOKKOS_INLINE_FUNCTION void operator()(const int a, value_type sums) const {
    const double s = inverse_sqrt_mass(a);
    const double w = pull_weights(a);
    for (int i = 0; i < 3; ++i) {
      double u = scaled_velocity(a, i);
      double x = positions(a, i);
      if (uphill) {
        x -= 0.5 * step * u * s;
        u = 0.0;
      }
      const double g = residual(a, i) * s;
      u += step * g;
      u = scale * ((1.0 - alpha) * u + mix * g);
      x += step * u * s;
      scaled_velocity(a, i) = u;
      positions(a, i) = x;
      sums[i] += w * x;
    }
  }
};

// p = Σ_a w_a x_a.
struct PullVectorFunctor {
  using value_type = double[];
  unsigned value_count = 3;
  ConstNodeVectors positions;
  Kokkos::View<const double*> pull_weights;

  KOKKOS_INLINE_FUNCTION void operator()(const int a, value_type sums) const {
    const double w = pull_weights(a);
    for (int i = 0; i < 3; ++i) sums[i] += w * positions(a, i);
  }
};

// Power iteration step: with the trial positions x0 + ε M^(−1/2) z and their forces f,
//   (A z)_a = M^(−1/2) K M^(−1/2) z ≈ −(f_a − f0_a) / (ε √m_a),
// stored into az; sums = {z·Az, Az·Az, z·z}.
struct StiffnessActionFunctor {
  using value_type = double[];
  unsigned value_count = 3;
  ConstNodeVectors forces, reference_forces, z;
  Kokkos::View<const double*> inverse_sqrt_mass;
  NodeVectors az;
  double inverse_epsilon;

  KOKKOS_INLINE_FUNCTION void operator()(const int a, value_type sums) const {
    for (int i = 0; i < 3; ++i) {
      const double value = -(forces(a, i) - reference_forces(a, i)) * inverse_epsilon * inverse_sqrt_mass(a);
      az(a, i) = value;
      sums[0] += z(a, i) * value;
      sums[1] += value * value;
      sums[2] += z(a, i) * z(a, i);
    }
  }
};

// A reproducible pseudo-random number in [−½, ½) from an integer (a 32-bit mix).
KOKKOS_INLINE_FUNCTION double hashed_uniform(unsigned int k) {
  k ^= k >> 16;
  k *= 0x7feb352dU;
  k ^= k >> 15;
  k *= 0x846ca68bU;
  k ^= k >> 16;
  return static_cast<double>(k) / 4294967296.0 - 0.5;
}

// The three sums of an array-reducing functor over the nodes [0, count), on the host.
template <class ExecSpace, class Functor>
std::array<double, 3> reduce3(const char* label, int count, const Functor& functor) {
  double sums[3] = {0.0, 0.0, 0.0};
  Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> result(sums, 3);
  Kokkos::parallel_reduce(label, Kokkos::RangePolicy<ExecSpace>(0, count), functor, result);
  Kokkos::fence();
  return {sums[0], sums[1], sums[2]};
}

}  // namespace static_relaxation
}  // namespace rouleau
