#pragma once
// The static solve's iteration (cells/static_equilibrium.hpp): FIRE 2.0 (Bitzek et al.,
// PRL 97, 170201, 2006; Guénolé et al., Comput. Mater. Sci. 175, 109584, 2020), a damped
// dynamic relaxation that needs only forces, in the mass-scaled variables y = M^(1/2) x:
// force g = M^(−1/2) r, velocity u = M^(1/2) v. It runs a fictitious dynamics M ẍ = r(x)
// with semi-implicit Euler steps, mixes the velocity toward the force,
// v ← (1 − α) v + α |v| r̂, grows the step while the power P = r·v stays positive, and,
// when P ≤ 0 (the system went uphill), steps back half a step, stops (v = 0) and halves the
// step. The step limit comes from λ_max of M^(−1/2) K M^(−1/2) (cells/stiffness_estimate.hpp)
// at the start, refreshed every few hundred steps as the deformed cell stiffens; no node
// moves more than max_step_length in one step.
#include <Kokkos_Core.hpp>
#include <array>

#include "cells/equilibrium_forces.hpp"
#include "cells/relaxation_masses.hpp"
#include "cells/static_equilibrium_options.hpp"
#include "cells/stiffness_estimate.hpp"

namespace rouleau {

template <class ExecSpace>
class BasicFireRelaxation {
 public:
  using NodeVectors = typename BasicEquilibriumForces<ExecSpace>::NodeVectors;

  // Moves the positions of `forces`; both arguments must outlive it.
  BasicFireRelaxation(BasicEquilibriumForces<ExecSpace>& forces, const BasicRelaxationMasses<ExecSpace>& masses);

  // One relaxation from the forces' positions at rest, at fixed pressure multipliers, to
  // max_a |r_a| ≤ report.tolerance; adds to report's iterations and force evaluations and
  // sets its convergence, stop reason, residual, eigenvalue and final step.
  void relax(const StaticEquilibriumOptions& options, StaticEquilibriumReport& report);

  // r = f_int + f_pressure + f_dead + f_pull (pull along p) into residual(), from the forces'
  // last evaluation; returns {P = Σ u·g, Σ u·u, Σ g·g}, g = M^(−1/2) r.
  std::array<double, 3> residual_and_power(const std::array<double, 3>& p);
  const NodeVectors& residual() const { return residual_; }
  // max_a |r_a| [pN].
  double largest_residual() const;

  // ---- the device kernels (public: CUDA lambdas may not live in private members)
  // The largest node displacement Δt |u_a|/√m_a the next FIRE move would make.
  double largest_move(bool uphill, double step, double alpha, double mix) const;
  // One FIRE move (kernels/static_relaxation.hpp); returns p at the new positions.
  std::array<double, 3> fire_move(bool uphill, double step, double alpha, double mix, double scale);

 private:
  // The velocity mixing and the move of one FIRE step from the power sums, no node moving
  // more than max_step_length; returns p at the new positions.
  std::array<double, 3> step_forward(const std::array<double, 3>& sums, bool uphill, double step, double alpha,
                                     double max_step_length);

  BasicEquilibriumForces<ExecSpace>& forces_;
  Kokkos::View<double*> inverse_sqrt_mass_;
  BasicStiffnessEstimate<ExecSpace> stiffness_;
  NodeVectors residual_, scaled_velocity_;
};

extern template class BasicFireRelaxation<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
