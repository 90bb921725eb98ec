// The static solve's FIRE 2.0 iteration (cells/fire_relaxation.hpp).
#include "cells/fire_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernels/static_relaxation.hpp"
#include "util/instantiate.hpp"

namespace rouleau {

namespace {
// FIRE 2.0's step size and mixing (Guénolé et al. 2020, Algorithm 2), from the stability
// limit Δt_max = step_fraction · 2/√λ_max: the step starts at Δt_max/10 and grows by
// step_increase (α shrinking by alpha_decrease) after delay_steps downhill steps; an
// uphill step halves it (not below Δt_max/500, not in the first delay_steps steps) and
// resets α.
struct FireStepControl {
  enum Kind { downhill, uphill, stuck };

  double step_max, step_min, step, alpha;
  int positive_steps = 0, uphill_steps = 0;

  FireStepControl(const double eigenvalue, const StaticEquilibriumOptions& options)
      : step_max(options.step_fraction * 2.0 / std::sqrt(eigenvalue)),
        step_min(0.02 * 0.1 * step_max),
        step(0.1 * step_max),
        alpha(options.alpha_start) {}

  // A new estimate of λ_max.
  void limit(const double eigenvalue, const StaticEquilibriumOptions& options) {
    step_max = options.step_fraction * 2.0 / std::sqrt(eigenvalue);
    step = std::min(step, step_max);
  }

  // The step and α after a step of power P; stuck (nothing changed) after more than
  // max_uphill_steps uphill steps in a row.
  Kind adapt(const double power, const int iteration, const StaticEquilibriumOptions& options) {
    if (power > 0.0) {
      ++positive_steps;
      uphill_steps = 0;
      if (positive_steps > options.delay_steps) {
        step = std::min(step * options.step_increase, step_max);
        alpha *= options.alpha_decrease;
      }
      return downhill;
    }
    positive_steps = 0;
    if (++uphill_steps > options.max_uphill_steps) return stuck;
    if (iteration >= options.delay_steps) {  // initial delay: no step decrease at first
      if (step * options.step_decrease >= step_min) step *= options.step_decrease;
      alpha = options.alpha_start;
    }
    return uphill;
  }
};
}  // namespace

template <class ExecSpace>
BasicFireRelaxation<ExecSpace>::BasicFireRelaxation(BasicEquilibriumForces<ExecSpace>& forces,
                                                    const BasicRelaxationMasses<ExecSpace>& masses)
    : forces_(forces),
      inverse_sqrt_mass_(masses.inverse_sqrt_masses()),
      stiffness_(forces, masses.inverse_sqrt_masses()),
      residual_("rouleau::StaticEquilibrium::residual", masses.masses().extent(0)),
      scaled_velocity_("rouleau::StaticEquilibrium::scaled_velocity", masses.masses().extent(0)) {}

template <class ExecSpace>
void BasicFireRelaxation<ExecSpace>::relax(const StaticEquilibriumOptions& options, StaticEquilibriumReport& report) {
  report.converged = false;
  // Step limit: linear stability of the scaled dynamics, Δt < 2/√λ_max.
  report.largest_eigenvalue = stiffness_.largest_eigenvalue(options.power_iterations, false, report.force_evaluations);
  if (!(report.largest_eigenvalue > 0.0))
    throw std::runtime_error("rouleau::StaticEquilibrium::solve: no positive stiffness eigenvalue found");
  FireStepControl control(report.largest_eigenvalue, options);

  Kokkos::deep_copy(scaled_velocity_, 0.0);
  std::array<double, 3> p = forces_.pull_vector();
  forces_.evaluate();
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
          stiffness_.largest_eigenvalue(options.update_power_iterations, true, report.force_evaluations);
      if (eigenvalue > 0.0) {
        report.largest_eigenvalue = eigenvalue;
        control.limit(eigenvalue, options);
      }
    }
    const FireStepControl::Kind kind = control.adapt(sums[0], iteration, options);
    if (kind == FireStepControl::stuck) {
      report.stop_reason = "uphill";
      report.max_residual = largest_residual();
      break;
    }
    p = step_forward(sums, kind == FireStepControl::uphill, control.step, control.alpha, options.max_step_length);
    forces_.evaluate();
    ++report.force_evaluations;
    sums = residual_and_power(p);
  }
  report.iterations += iteration;
  report.final_step = control.step;
}

template <class ExecSpace>
std::array<double, 3> BasicFireRelaxation<ExecSpace>::step_forward(const std::array<double, 3>& sums, const bool uphill,
                                                                   const double step, const double alpha,
                                                                   const double max_step_length) {
  // |u| after u ← u + Δt g (u ← 0 first when uphill): |u|² + 2Δt u·g + Δt²|g|²
  const double uu = uphill ? 0.0 : sums[1];
  const double ug = uphill ? 0.0 : sums[0];
  const double new_speed2 = std::max(0.0, uu + 2.0 * step * ug + step * step * sums[2]);
  const double mix = sums[2] > 0.0 ? alpha * std::sqrt(new_speed2 / sums[2]) : 0.0;
  // Cap the largest nodal move at max_step_length (one factor for all nodes).
  const double move = largest_move(uphill, step, alpha, mix);
  const double scale = move > max_step_length ? max_step_length / move : 1.0;
  return fire_move(uphill, step, alpha, mix, scale);
}

template <class ExecSpace>
std::array<double, 3> BasicFireRelaxation<ExecSpace>::residual_and_power(const std::array<double, 3>& p) {
  static_relaxation::ResidualPowerFunctor functor;
  functor.internal_forces = forces_.internal_forces();
  functor.constraint_forces = forces_.pressure_forces();
  functor.dead_loads = forces_.dead_loads();
  functor.scaled_velocity = scaled_velocity_;
  functor.pull_weights = forces_.pull_weights();
  functor.inverse_sqrt_mass = inverse_sqrt_mass_;
  functor.residual = residual_;
  const std::array<double, 3> pull = forces_.pull_along(p);
  for (int i = 0; i < 3; ++i) functor.pull[i] = pull[i];
  return static_relaxation::reduce3<ExecSpace>("rouleau::StaticEquilibrium::residual_and_power",
                                               static_cast<int>(residual_.extent(0)), functor);
}

template <class ExecSpace>
double BasicFireRelaxation<ExecSpace>::largest_residual() const {
  auto residual = residual_;
  double largest = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::StaticEquilibrium::largest_residual", Kokkos::RangePolicy<ExecSpace>(0, residual.extent(0)),
      KOKKOS_LAMBDA(const int a, double& value) {
        const double r2 =
            residual(a, 0) * residual(a, 0) + residual(a, 1) * residual(a, 1) + residual(a, 2) * residual(a, 2);
        if (r2 > value) value = r2;
      },
      Kokkos::Max<double>(largest));
  return std::sqrt(largest);
}

template <class ExecSpace>
double BasicFireRelaxation<ExecSpace>::largest_move(bool uphill, double step, double alpha, double mix) const {
  // max_a Δt |u_a'|/√m_a with u' = (1 − α)(u + Δt g) + mix g (u = 0 first when uphill)
  auto velocity = scaled_velocity_;
  auto residual = residual_;
  auto inverse_sqrt_mass = inverse_sqrt_mass_;
  const double keep = uphill ? 0.0 : 1.0;
  double largest = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::StaticEquilibrium::largest_move", Kokkos::RangePolicy<ExecSpace>(0, residual.extent(0)),
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
std::array<double, 3> BasicFireRelaxation<ExecSpace>::fire_move(bool uphill, double step, double alpha, double mix,
                                                                double scale) {
  static_relaxation::FireMoveFunctor functor;
  functor.positions = forces_.positions();
  functor.scaled_velocity = scaled_velocity_;
  functor.residual = residual_;
  functor.pull_weights = forces_.pull_weights();
  functor.inverse_sqrt_mass = inverse_sqrt_mass_;
  functor.uphill = uphill;
  functor.step = step;
  functor.alpha = alpha;
  functor.mix = mix;
  functor.scale = scale;
  return static_relaxation::reduce3<ExecSpace>("rouleau::StaticEquilibrium::fire_move",
                                               static_cast<int>(residual_.extent(0)), functor);
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicFireRelaxation)

}  // namespace rouleau
