#include "cells/static_equilibrium.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "kernels/cell_surface.hpp"
#include "kernels/tet4.hpp"
#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {
namespace static_equilibrium_detail {

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

template <class ExecSpace, class Functor>
std::array<double, 3> reduce3(const char* label, int count, const Functor& functor) {
  double sums[3] = {0.0, 0.0, 0.0};
  Kokkos::View<double*, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>> result(sums, 3);
  Kokkos::parallel_reduce(label, Kokkos::RangePolicy<ExecSpace>(0, count), functor, result);
  Kokkos::fence();
  return {sums[0], sums[1], sums[2]};
}

}  // namespace static_equilibrium_detail

using namespace static_equilibrium_detail;

// ---- BasicStaticEquilibrium

template <class ExecSpace>
BasicStaticEquilibrium<ExecSpace>::BasicStaticEquilibrium(Population& cells) : cells_(cells) {
  const int n = cells.num_nodes();
  mass_ = Kokkos::View<double*>("rouleau::StaticEquilibrium::mass", n);
  inverse_sqrt_mass_ = Kokkos::View<double*>("rouleau::StaticEquilibrium::inverse_sqrt_mass", n);
  pull_weights_ = Kokkos::View<double*>("rouleau::StaticEquilibrium::pull_weights", n);
  device_cell_pressures_ = Kokkos::View<double*>("rouleau::StaticEquilibrium::cell_pressures", cells.num_cells());
  dead_loads_ = NodeVectors("rouleau::StaticEquilibrium::dead_loads", n);
  residual_ = NodeVectors("rouleau::StaticEquilibrium::residual", n);
  scaled_velocity_ = NodeVectors("rouleau::StaticEquilibrium::scaled_velocity", n);
  scratch_a_ = NodeVectors("rouleau::StaticEquilibrium::scratch_a", n);
  scratch_b_ = NodeVectors("rouleau::StaticEquilibrium::scratch_b", n);
  constraint_forces_ = NodeVectors("rouleau::StaticEquilibrium::constraint_forces", n);
  cell_pressures_.assign(cells.num_cells(), 0.0);
  compute_masses();
}

template <class ExecSpace>
void BasicStaticEquilibrium<ExecSpace>::compute_masses() {
  ProfilingRegion region("rouleau::StaticEquilibrium::masses");
  // Block-Gershgorin bound of the small-strain stiffness of one tetrahedron per unit
  // P-wave modulus (λ + 2μ): its block K_ab = V0 [(λ + μ) ∇N_a ⊗ ∇N_b + μ (∇N_a·∇N_b) I]
  // has norm ≤ V0 (λ + 2μ) |∇N_a| |∇N_b|, so m_a = Σ_e V0 |∇N_a| Σ_b |∇N_b| bounds row a.
  auto element_nodes = cells_.element_nodes();
  auto inverse_edge_matrix = cells_.inverse_edge_matrix();
  auto reference_volume = cells_.reference_volume();
  auto mass = mass_;
  Kokkos::deep_copy(mass, 0.0);
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::masses", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_elements()),
      KOKKOS_LAMBDA(const int e) {
        Mat3 inverse;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) inverse.m[i][j] = inverse_edge_matrix(e, i, j);
        double gradient[4][3];
        Tet4::shape_gradients(inverse, gradient);
        double length[4], total = 0.0;
        for (int a = 0; a < 4; ++a) {
          length[a] =
              sqrt(gradient[a][0] * gradient[a][0] + gradient[a][1] * gradient[a][1] + gradient[a][2] * gradient[a][2]);
          total += length[a];
        }
        for (int a = 0; a < 4; ++a)
          Kokkos::atomic_add(&mass(element_nodes(e, a)), reference_volume(e) * length[a] * total);
      });
  auto inverse_sqrt_mass = inverse_sqrt_mass_;
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::inverse_sqrt_mass", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_nodes()),
      KOKKOS_LAMBDA(const int a) { inverse_sqrt_mass(a) = mass(a) > 0.0 ? 1.0 / sqrt(mass(a)) : 0.0; });
  Kokkos::fence();
}

template <class ExecSpace>
void BasicStaticEquilibrium<ExecSpace>::set_pull(const Kokkos::View<double*>& signed_weights, double force) {
  if (static_cast<int>(signed_weights.extent(0)) != cells_.num_nodes())
    throw std::invalid_argument("rouleau::StaticEquilibrium::set_pull: one weight per node expected");
  if (!(force >= 0.0)) throw std::invalid_argument("rouleau::StaticEquilibrium::set_pull: force must be >= 0");
  Kokkos::deep_copy(pull_weights_, signed_weights);
  pull_force_ = force;
}

template <class ExecSpace>
void BasicStaticEquilibrium<ExecSpace>::set_volume_constraint(double stiffness) {
  if (!(stiffness >= 0.0))
    throw std::invalid_argument("rouleau::StaticEquilibrium::set_volume_constraint: stiffness must be >= 0");
  volume_stiffness_ = stiffness;
  // V0_c from the reference positions (measures() reads the current ones).
  auto positions = cells_.positions();
  NodeVectors current("rouleau::StaticEquilibrium::current_positions", cells_.num_nodes());
  Kokkos::deep_copy(current, positions);
  Kokkos::deep_copy(positions, cells_.reference_positions());
  reference_volumes_.clear();
  for (const CellMeasures& m : cells_.measures()) reference_volumes_.push_back(m.volume);
  Kokkos::deep_copy(positions, current);
  volume_multipliers_.assign(cells_.num_cells(), 0.0);
  cell_pressures_.assign(cells_.num_cells(), 0.0);
  Kokkos::deep_copy(constraint_forces_, 0.0);
}

template <class ExecSpace>
void BasicStaticEquilibrium<ExecSpace>::evaluate_forces() {
  cells_.compute_internal_forces();
  if (volume_stiffness_ <= 0.0) return;
  // p_c = λ_c − k (V_c − V0_c), then f_a = p_c Σ_{t ∋ a} n_t / 3 (∂V/∂x_a of the closed
  // outer surface; the x_a × Σ(x_c − x_b) terms of ∂(x0·(x1 × x2))/6 cancel around a node).
  const std::vector<CellMeasures> measures = cells_.measures();
  cell_volumes_.resize(measures.size());
  auto host_pressures = Kokkos::create_mirror_view(device_cell_pressures_);
  for (std::size_t c = 0; c < measures.size(); ++c) {
    cell_volumes_[c] = measures[c].volume;
    cell_pressures_[c] = volume_multipliers_[c] - volume_stiffness_ * (measures[c].volume - reference_volumes_[c]);
    host_pressures(c) = cell_pressures_[c];
  }
  Kokkos::deep_copy(device_cell_pressures_, host_pressures);
  auto forces = constraint_forces_;
  auto positions = cells_.positions();
  auto triangles = cells_.surface_triangles();
  auto triangle_cell = cells_.triangle_cell();
  auto pressures = device_cell_pressures_;
  Kokkos::deep_copy(forces, 0.0);
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::pressure_forces", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_surface_triangles()),
      KOKKOS_LAMBDA(const int t) {
        double y[3][3];
        for (int k = 0; k < 3; ++k)
          for (int i = 0; i < 3; ++i) y[k][i] = positions(triangles(t, k), i);
        double n[3];
        triangle_area_vector(y, n);
        const double p = pressures(triangle_cell(t)) / 3.0;
        for (int k = 0; k < 3; ++k)
          for (int i = 0; i < 3; ++i) Kokkos::atomic_add(&forces(triangles(t, k), i), p * n[i]);
      });
}

template <class ExecSpace>
void BasicStaticEquilibrium<ExecSpace>::conservative_forces(const NodeVectors& out) const {
  auto internal = cells_.internal_forces();
  auto constraint = constraint_forces_;
  Kokkos::parallel_for(
      "rouleau::StaticEquilibrium::conservative_forces", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_nodes()),
      KOKKOS_LAMBDA(const int a) {
        for (int i = 0; i < 3; ++i) out(a, i) = internal(a, i) + constraint(a, i);
      });
}

template <class ExecSpace>
double BasicStaticEquilibrium<ExecSpace>::applied_load() const {
  auto dead = dead_loads_;
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::StaticEquilibrium::dead_load_magnitude", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_nodes()),
      KOKKOS_LAMBDA(const int a, double& s) {
        s += sqrt(dead(a, 0) * dead(a, 0) + dead(a, 1) * dead(a, 1) + dead(a, 2) * dead(a, 2));
      },
      sum);
  return pull_force_ + 0.5 * sum;
}

template <class ExecSpace>
std::array<double, 3> BasicStaticEquilibrium<ExecSpace>::pull_vector() const {
  PullVectorFunctor functor;
  functor.positions = cells_.positions();
  functor.pull_weights = pull_weights_;
  return reduce3<ExecSpace>("rouleau::StaticEquilibrium::pull_vector", cells_.num_nodes(), functor);
}

template <class ExecSpace>
std::array<double, 3> BasicStaticEquilibrium<ExecSpace>::residual_and_power(const std::array<double, 3>& p) {
  ResidualPowerFunctor functor;
  functor.internal_forces = cells_.internal_forces();
  functor.constraint_forces = constraint_forces_;
  functor.dead_loads = dead_loads_;
  functor.scaled_velocity = scaled_velocity_;
  functor.pull_weights = pull_weights_;
  functor.inverse_sqrt_mass = inverse_sqrt_mass_;
  functor.residual = residual_;
  // f_pull = F p/|p| on the weights (no pull while the groups coincide or F = 0)
  const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  const double scale = (pull_force_ > 0.0 && length > 0.0) ? pull_force_ / length : 0.0;
  for (int i = 0; i < 3; ++i) functor.pull[i] = scale * p[i];
  return reduce3<ExecSpace>("rouleau::StaticEquilibrium::residual_and_power", cells_.num_nodes(), functor);
}

template <class ExecSpace>
double BasicStaticEquilibrium<ExecSpace>::largest_residual() const {
  auto residual = residual_;
  double largest = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::StaticEquilibrium::largest_residual", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_nodes()),
      KOKKOS_LAMBDA(const int a, double& value) {
        const double r2 =
            residual(a, 0) * residual(a, 0) + residual(a, 1) * residual(a, 1) + residual(a, 2) * residual(a, 2);
        if (r2 > value) value = r2;
      },
      Kokkos::Max<double>(largest));
  return std::sqrt(largest);
}

template <class ExecSpace>
double BasicStaticEquilibrium<ExecSpace>::compute_residual() {
  evaluate_forces();
  residual_and_power(pull_vector());
  return largest_residual();
}

template <class ExecSpace>
double BasicStaticEquilibrium<ExecSpace>::largest_move(bool uphill, double step, double alpha, double mix) const {
  // max_a Δt |u_a'|/√m_a with u' = (1 − α)(u + Δt g) + mix g (u = 0 first when uphill)
  auto velocity = scaled_velocity_;
  auto residual = residual_;
  auto inverse_sqrt_mass = inverse_sqrt_mass_;
  const double keep = uphill ? 0.0 : 1.0;
  double largest = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::StaticEquilibrium::largest_move", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_nodes()),
      KOKKOS_LAMBDA(const int a, double& value) {
        const double s = inverse_sqrt_mass(a);
        double u2 = 0.0;
        for (int i = 0; i < 3; ++i) {
          const double g = residual(a, i) * s;
          const double u = (1.0 - alpha) * (keep * velocity(a, i) + step * g) + mix * g;
          u2 += u * u;
        }
        const double move2 = step * step * u2 * s * s;
        if (move2 > value) value = move2;
      },
      Kokkos::Max<double>(largest));
  return std::sqrt(largest);
}

template <class ExecSpace>
std::array<double, 3> BasicStaticEquilibrium<ExecSpace>::fire_move(bool uphill, double step, double alpha, double mix,
                                                                   double scale) {
  FireMoveFunctor functor;
  functor.positions = cells_.positions();
  functor.scaled_velocity = scaled_velocity_;
  functor.residual = residual_;
  functor.pull_weights = pull_weights_;
  functor.inverse_sqrt_mass = inverse_sqrt_mass_;
  functor.uphill = uphill;
  functor.step = step;
  functor.alpha = alpha;
  functor.mix = mix;
  functor.scale = scale;
  return reduce3<ExecSpace>("rouleau::StaticEquilibrium::fire_move", cells_.num_nodes(), functor);
}

template <class ExecSpace>
double BasicStaticEquilibrium<ExecSpace>::estimate_largest_eigenvalue(int iterations, bool warm_start,
                                                                      int& force_evaluations) {
  ProfilingRegion region("rouleau::StaticEquilibrium::largest_eigenvalue");
  // Power iteration z ← A z / |A z| on A = M^(−1/2) K M^(−1/2), K z' ≈ −(f(x0 + ε z') − f(x0))/ε
  // with f = f_int + f_pressure (forward differences, the largest nodal displacement ε |z'_a|
  // 1e-7 μm); λ ≈ z·Az / z·z. The pull's geometric stiffness F/|p| is left out (small).
  const int n = cells_.num_nodes();
  auto positions = cells_.positions();
  auto inverse_sqrt_mass = inverse_sqrt_mass_;
  NodeVectors x0("rouleau::StaticEquilibrium::x0", n), f0("rouleau::StaticEquilibrium::f0", n),
      f("rouleau::StaticEquilibrium::f", n);
  Kokkos::deep_copy(x0, positions);
  evaluate_forces();
  ++force_evaluations;
  conservative_forces(f0);
  auto z = scratch_a_;
  auto az = scratch_b_;
  if (!warm_start)
    Kokkos::parallel_for(
        "rouleau::StaticEquilibrium::power_start", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int a) {
          for (int i = 0; i < 3; ++i)
            z(a, i) = hashed_uniform(static_cast<unsigned int>(3 * a + i) * 2654435761U + 12345U);
        });
  double eigenvalue = 0.0;
  for (int k = 0; k < iterations; ++k) {
    double largest = 0.0;
    Kokkos::parallel_reduce(
        "rouleau::StaticEquilibrium::power_scale", Kokkos::RangePolicy<ExecSpace>(0, n),
        KOKKOS_LAMBDA(const int a, double& value) {
          const double d = sqrt(z(a, 0) * z(a, 0) + z(a, 1) * z(a, 1) + z(a, 2) * z(a, 2)) * inverse_sqrt_mass(a);
          if (d > value) value = d;
        },
        Kokkos::Max<double>(largest));
    if (!(largest > 0.0)) break;
    const double epsilon = 1e-7 / largest;
    Kokkos::parallel_for(
        "rouleau::StaticEquilibrium::power_trial", Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int a) {
          for (int i = 0; i < 3; ++i) positions(a, i) = x0(a, i) + epsilon * z(a, i) * inverse_sqrt_mass(a);
        });
    evaluate_forces();
    ++force_evaluations;
    conservative_forces(f);
    StiffnessActionFunctor functor;
    functor.forces = f;
    functor.reference_forces = f0;
    functor.z = z;
    functor.inverse_sqrt_mass = inverse_sqrt_mass;
    functor.az = az;
    functor.inverse_epsilon = 1.0 / epsilon;
    const auto sums = reduce3<ExecSpace>("rouleau::StaticEquilibrium::power_action", n, functor);
    if (!(sums[1] > 0.0) || !(sums[2] > 0.0)) break;
    eigenvalue = sums[0] / sums[2];
    const double inverse_norm = 1.0 / std::sqrt(sums[1]);
    Kokkos::parallel_for(
        "rouleau::StaticEquilibrium::power_normalize", Kokkos::RangePolicy<ExecSpace>(0, n),
        KOKKOS_LAMBDA(const int a) {
          for (int i = 0; i < 3; ++i) z(a, i) = az(a, i) * inverse_norm;
        });
  }
  // Back to x0 and its forces.
  Kokkos::deep_copy(positions, x0);
  evaluate_forces();
  ++force_evaluations;
  return eigenvalue;
}

template <class ExecSpace>
StaticEquilibriumReport BasicStaticEquilibrium<ExecSpace>::solve(const StaticEquilibriumOptions& options) {
  ProfilingRegion region("rouleau::StaticEquilibrium::solve");
  const auto start = std::chrono::steady_clock::now();
  StaticEquilibriumReport report;

  // Dead loads must be balanced, or the body accelerates away and no equilibrium exists.
  {
    auto dead = dead_loads_;
    double sums[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i) {
      double s = 0.0;
      Kokkos::parallel_reduce(
          "rouleau::StaticEquilibrium::dead_load_sum", Kokkos::RangePolicy<ExecSpace>(0, cells_.num_nodes()),
          KOKKOS_LAMBDA(const int a, double& value) { value += dead(a, i); }, s);
      sums[i] = s;
    }
    const double magnitude = applied_load() - pull_force_;
    const double net = std::sqrt(sums[0] * sums[0] + sums[1] * sums[1] + sums[2] * sums[2]);
    if (net > 0.0 && net > 1e-9 * magnitude) {
      std::ostringstream msg;
      msg << "rouleau::StaticEquilibrium::solve: the dead loads add up to " << net << " pN (of " << 2 * magnitude
          << " pN in all): unbalanced loads have no static equilibrium";
      throw std::invalid_argument(msg.str());
    }
  }
  report.applied_load = applied_load();
  report.tolerance = options.relative_tolerance * std::max(report.applied_load, options.load_floor);

  if (volume_stiffness_ <= 0.0) {
    relax(options, report);
  } else {
    // Augmented Lagrangian: relax at fixed multipliers λ_c, then λ_c ← p_c.
    for (;;) {
      relax(options, report);
      report.largest_volume_error = 0.0;
      for (std::size_t c = 0; c < reference_volumes_.size(); ++c)
        report.largest_volume_error = std::max(
            report.largest_volume_error, std::fabs(cell_volumes_[c] - reference_volumes_[c]) / reference_volumes_[c]);
      if (!report.converged || report.largest_volume_error <= options.volume_tolerance) break;
      if (report.volume_updates >= options.max_volume_updates) {
        report.converged = false;
        report.stop_reason = "volume";
        break;
      }
      for (std::size_t c = 0; c < reference_volumes_.size(); ++c) volume_multipliers_[c] = cell_pressures_[c];
      ++report.volume_updates;
    }
    for (const double p : cell_pressures_) report.largest_pressure = std::max(report.largest_pressure, std::fabs(p));
  }
  report.strain_energy = cells_.compute_internal_forces_and_energy();
  ++report.force_evaluations;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

template <class ExecSpace>
void BasicStaticEquilibrium<ExecSpace>::relax(const StaticEquilibriumOptions& options,
                                              StaticEquilibriumReport& report) {
  report.converged = false;
  // Step limit: linear stability of the scaled dynamics, Δt < 2/√λ_max.
  report.largest_eigenvalue = estimate_largest_eigenvalue(options.power_iterations, false, report.force_evaluations);
  if (!(report.largest_eigenvalue > 0.0))
    throw std::runtime_error("rouleau::StaticEquilibrium::solve: no positive stiffness eigenvalue found");
  double step_max = options.step_fraction * 2.0 / std::sqrt(report.largest_eigenvalue);
  const double step_min = 0.02 * 0.1 * step_max;
  double step = 0.1 * step_max;
  double alpha = options.alpha_start;
  int positive_steps = 0, uphill_steps = 0;

  Kokkos::deep_copy(scaled_velocity_, 0.0);
  std::array<double, 3> p = pull_vector();
  evaluate_forces();
  ++report.force_evaluations;
  std::array<double, 3> sums = residual_and_power(p);
  report.stop_reason = "max_iterations";
  int iteration = 0;
  for (;; ++iteration) {
    if (!std::isfinite(sums[0]) || !std::isfinite(sums[2])) {
      report.stop_reason = "not finite";
      break;
    }
    if (iteration % std::max(1, options.check_interval) == 0 || iteration >= options.max_iterations) {
      report.max_residual = largest_residual();
      if (report.max_residual <= report.tolerance) {
        report.converged = true;
        report.stop_reason = "converged";
        break;
      }
      if (iteration >= options.max_iterations) break;
    }
    // The step limit follows the stiffness of the deformed cell (estimated at the current
    // positions, which the estimate leaves unchanged, with their forces and residual).
    if (options.eigenvalue_interval > 0 && iteration > 0 && iteration % options.eigenvalue_interval == 0) {
      const double eigenvalue =
          estimate_largest_eigenvalue(options.update_power_iterations, true, report.force_evaluations);
      if (eigenvalue > 0.0) {
        report.largest_eigenvalue = eigenvalue;
        step_max = options.step_fraction * 2.0 / std::sqrt(eigenvalue);
        step = std::min(step, step_max);
      }
    }
    // FIRE 2.0 (Guénolé et al. 2020, Algorithm 2)
    const double power = sums[0];
    bool uphill = false;
    if (power > 0.0) {
      ++positive_steps;
      uphill_steps = 0;
      if (positive_steps > options.delay_steps) {
        step = std::min(step * options.step_increase, step_max);
        alpha *= options.alpha_decrease;
      }
    } else {
      positive_steps = 0;
      if (++uphill_steps > options.max_uphill_steps) {
        report.stop_reason = "uphill";
        report.max_residual = largest_residual();
        break;
      }
      if (iteration >= options.delay_steps) {  // initial delay: no step decrease at first
        if (step * options.step_decrease >= step_min) step *= options.step_decrease;
        alpha = options.alpha_start;
      }
      uphill = true;
    }
    // |u| after u ← u + Δt g (u ← 0 first when uphill): |u|² + 2Δt u·g + Δt²|g|²
    const double uu = uphill ? 0.0 : sums[1];
    const double ug = uphill ? 0.0 : sums[0];
    const double new_speed2 = std::max(0.0, uu + 2.0 * step * ug + step * step * sums[2]);
    const double mix = sums[2] > 0.0 ? alpha * std::sqrt(new_speed2 / sums[2]) : 0.0;
    // Cap the largest nodal move at max_step_length (one factor for all nodes).
    const double move = largest_move(uphill, step, alpha, mix);
    const double scale = move > options.max_step_length ? options.max_step_length / move : 1.0;
    p = fire_move(uphill, step, alpha, mix, scale);
    evaluate_forces();
    ++report.force_evaluations;
    sums = residual_and_power(p);
  }
  report.iterations += iteration;
  report.final_step = step;
}

// ---- BasicStretchPatches

template <class ExecSpace>
BasicStretchPatches<ExecSpace>::BasicStretchPatches(const BasicCellPopulation<ExecSpace>& cells, int cell,
                                                    std::array<double, 3> direction,
                                                    std::array<double, 3> in_plane_transverse, double contact_diameter)
    : cell_(cell), transverse_(in_plane_transverse) {
  if (cell < 0 || cell >= cells.num_cells())
    throw std::invalid_argument("rouleau::StretchPatches: no cell " + std::to_string(cell));
  if (!(contact_diameter > 0.0)) throw std::invalid_argument("rouleau::StretchPatches: contact diameter must be > 0");
  const double length =
      std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  if (!(length > 0.0)) throw std::invalid_argument("rouleau::StretchPatches: zero direction");
  for (double& d : direction) d /= length;

  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.positions());
  auto area = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.surface_area_weights());
  const int first = cells.cell_first_node()[cell];
  const int count = cells.cell_node_count()[cell];
  const std::array<double, 3> centroid = cells.measures()[cell].centroid;

  // The ends: the centroid moved along ±direction to the extreme node projections.
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (int a = first; a < first + count; ++a) {
    double s = 0.0;
    for (int i = 0; i < 3; ++i) s += (x(a, i) - centroid[i]) * direction[i];
    lowest = std::min(lowest, s);
    highest = std::max(highest, s);
  }
  std::array<double, 3> end_positive, end_negative;
  for (int i = 0; i < 3; ++i) {
    end_positive[i] = centroid[i] + highest * direction[i];
    end_negative[i] = centroid[i] + lowest * direction[i];
  }
  const double radius2 = 0.25 * contact_diameter * contact_diameter;
  signed_weights_ = Kokkos::View<double*>("rouleau::StretchPatches::signed_weights", cells.num_nodes());
  auto weights = Kokkos::create_mirror_view(signed_weights_);
  Kokkos::deep_copy(weights, 0.0);
  for (int a = first; a < first + count; ++a) {
    if (!(area(a) > 0.0)) continue;  // not on the outer surface
    ++surface_nodes_;
    double d_positive = 0.0, d_negative = 0.0;
    for (int i = 0; i < 3; ++i) {
      d_positive += (x(a, i) - end_positive[i]) * (x(a, i) - end_positive[i]);
      d_negative += (x(a, i) - end_negative[i]) * (x(a, i) - end_negative[i]);
    }
    if (d_positive <= radius2) {
      weights(a) = area(a);
      positive_area_ += area(a);
      ++positive_nodes_;
    } else if (d_negative <= radius2) {
      weights(a) = -area(a);
      negative_area_ += area(a);
      ++negative_nodes_;
    }
  }
  if (positive_nodes_ == 0 || negative_nodes_ == 0)
    throw std::runtime_error(
        "rouleau::StretchPatches: an end patch holds no surface node (contact diameter too small "
        "for the mesh?)");
  for (int a = first; a < first + count; ++a) weights(a) /= weights(a) > 0.0 ? positive_area_ : negative_area_;
  Kokkos::deep_copy(signed_weights_, weights);
}

template <class ExecSpace>
StretchDiameters BasicStretchPatches<ExecSpace>::diameters(const BasicCellPopulation<ExecSpace>& cells) const {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.positions());
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), signed_weights_);
  const int first = cells.cell_first_node()[cell_];
  const int count = cells.cell_node_count()[cell_];
  StretchDiameters result;
  // Pull direction d̂ = p/|p|, p = Σ w_a x_a; transverse t̂ = the given in-plane direction
  // made perpendicular to d̂.
  std::array<double, 3> p{0.0, 0.0, 0.0};
  for (int a = first; a < first + count; ++a)
    for (int i = 0; i < 3; ++i) p[i] += w(a) * x(a, i);
  const double p_length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  for (int i = 0; i < 3; ++i) result.pull_direction[i] = p[i] / p_length;
  const auto& d = result.pull_direction;
  const double along = transverse_[0] * d[0] + transverse_[1] * d[1] + transverse_[2] * d[2];
  std::array<double, 3> t;
  for (int i = 0; i < 3; ++i) t[i] = transverse_[i] - along * d[i];
  const double t_length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  for (double& ti : t) ti /= t_length;
  double axial_low = std::numeric_limits<double>::infinity(), axial_high = -axial_low;
  double transverse_low = axial_low, transverse_high = axial_high;
  for (int a = first; a < first + count; ++a) {
    const double s = x(a, 0) * d[0] + x(a, 1) * d[1] + x(a, 2) * d[2];
    const double q = x(a, 0) * t[0] + x(a, 1) * t[1] + x(a, 2) * t[2];
    axial_low = std::min(axial_low, s);
    axial_high = std::max(axial_high, s);
    transverse_low = std::min(transverse_low, q);
    transverse_high = std::max(transverse_high, q);
  }
  result.axial = axial_high - axial_low;
  result.transverse = transverse_high - transverse_low;
  return result;
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicStaticEquilibrium)
ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicStretchPatches)

}  // namespace rouleau
