#pragma once
// Static equilibrium of the cells under prescribed external forces, for the solid alone
// (no fluid): find the positions x with
//
//   r(x) = f_int(x) + f_ext(x) = 0,   f_int = −∂W/∂x (the population's internal forces:
//   neo-Hookean, paper eqs. 2, 9, 10, with the kind's optional strain hardening and global
//   area constraint),
//
// i.e. a stationary point of the total potential energy Π = W + Π_ext (f_ext = −∂Π_ext/∂x;
// W the elastic energy, strain energy plus area term). Used for
// the optical-tweezers stretching test (Mills et al. 2004; docs/method.md, "Static stretch":
// a static solve of the solid alone, the force spread over the nodes within a 2 μm patch
// at each end).
//
// Method: FIRE 2.0 (Bitzek et al., PRL 97, 170201, 2006; Guénolé et al., Comput. Mater.
// Sci. 175, 109584, 2020), a damped dynamic relaxation that needs only forces. It runs a
// fictitious dynamics M ẍ = r(x) with semi-implicit Euler steps, mixes the velocity
// toward the force, v ← (1 − α) v + α |v| r̂, grows the step while the power P = r·v stays
// positive, and, when P ≤ 0 (the system went uphill), steps back half a step, stops
// (v = 0) and halves the step. The fictitious masses are the dynamic-relaxation ones
// (Underwood 1983): a block-Gershgorin bound of the small-strain stiffness per unit
// modulus, m_a = Σ_{e ∋ a} V0_e |∇N_a| Σ_b |∇N_b|, so that every node has about the same
// stable step; the step limit itself comes from a power iteration on M^(−1/2) K M^(−1/2)
// (K by finite differences of the forces) at the start, refreshed every few hundred steps
// as the deformed cell stiffens. The iteration works in the mass-scaled variables
// y = M^(1/2) x: force g = M^(−1/2) r, velocity u = M^(1/2) v.
//
// Rigid-body modes: nothing is pinned. The internal forces conserve linear and angular
// momentum exactly (Σ f_int = 0, Σ x × f_int = 0), and so does the pull between two node
// groups, which acts along the line through their weighted centres (Σ f = 0 and
// Σ x × f = 0 in every configuration). Starting at rest, FIRE's updates (v += Δt M⁻¹ r,
// mixing with M⁻¹ r) then keep Σ m v = 0 and Σ m x × v = 0 to round-off: the
// mass-weighted centroid does not move and no rigid spin is excited, so the translation
// and rotation null modes of the stiffness never need removing. (The pull's direction
// follows the patches, as two traps pull their beads apart along the line joining them.)
// Dead loads must add up to zero (checked); a net moment of theirs turns the body until it
// vanishes, as it must at any static equilibrium.
//
// Convergence: max_a |r_a| ≤ relative_tolerance · L, with L the applied load (the pull
// force plus half the sum of the dead loads' magnitudes, at least load_floor).
//
// Robustness: no node moves more than max_step_length in one step (all velocities are
// scaled down together, which keeps the momenta zero), so a large load applied at once
// cannot invert the thin shell's elements in the first steps.
//
// Optional enclosed-volume constraint (the incompressible cytoplasm of a shell cell, which
// the coupled model gets from the fluid inside): each cell's volume V_c (enclosed by its
// outer surface) is held at its reference value V0_c by a uniform internal pressure,
//   f_a = p_c ∂V_c/∂x_a = p_c Σ_{t ∋ a} n_t / 3   (n_t: the triangle's area vector),
// found by an augmented Lagrangian: p_c = λ_c − k (V_c − V0_c) during a relaxation, then
// λ_c ← p_c and relax again, until |V_c − V0_c| ≤ volume_tolerance · V0_c. Its force is
// the global volume constraint's (kernels/global_constraints.hpp) with P_c = −p_c.
//
// The solver iterates on its own copy of the positions and writes the population's once,
// at the end of a solve. Its parts, one file each: the options and the report
// (static_equilibrium_options.hpp), the fictitious masses (relaxation_masses.hpp), the
// forces and loads at the solver's positions (equilibrium_forces.hpp), the power iteration
// for λ_max (stiffness_estimate.hpp), the FIRE iteration (fire_relaxation.hpp) and their
// device kernels (kernels/static_relaxation.hpp); this class runs the volume constraint's
// outer loop around them. The optical-tweezers patches and diameters: stretch_patches.hpp.
#include <Kokkos_Core.hpp>
#include <array>
#include <vector>

#include "cells/cell_population.hpp"
#include "cells/equilibrium_forces.hpp"
#include "cells/fire_relaxation.hpp"
#include "cells/relaxation_masses.hpp"
#include "cells/static_equilibrium_options.hpp"

namespace rouleau {

template <class ExecSpace>
class BasicStaticEquilibrium {
 public:
  using Population = BasicCellPopulation<ExecSpace>;
  using NodeVectors = typename Population::NodeVectors;

  // Solves for `cells` (the population must outlive the solver), writing their positions
  // at the end of each solve(). Fictitious masses are computed here, once, from the
  // reference configuration.
  explicit BasicStaticEquilibrium(Population& cells);

  // Dead loads f_dead (node, 3) [pN], zero at construction: fill the View. They must add
  // up to zero (solve() throws std::invalid_argument otherwise).
  const NodeVectors& dead_loads() const { return forces_.dead_loads(); }

  // A pull of magnitude `force` [pN] between two node groups along the line through their
  // weighted centres: w_a > 0 on one group (summing to 1), w_a < 0 on the other (summing
  // to −1), 0 elsewhere. With p = Σ_a w_a x_a (the vector from the negative group's centre
  // to the positive one's), f_ext,a = F w_a p/|p| = −∂Π_ext/∂x_a with Π_ext = −F |p|.
  void set_pull(const Kokkos::View<double*>& signed_weights, double force) { forces_.set_pull(signed_weights, force); }
  void clear_pull() { forces_.clear_pull(); }
  double pull_force() const { return forces_.pull_force(); }

  // Holds every cell's enclosed volume at its value in the reference configuration by an
  // internal pressure (augmented Lagrangian with penalty `stiffness` k [pN/μm⁵]); k = 0
  // turns the constraint off. The pressures start at zero.
  void set_volume_constraint(double stiffness) { forces_.set_volume_constraint(stiffness); }
  // The cells' internal pressures p_c [Pa] (zero without the constraint).
  const std::vector<double>& cell_pressures() const { return forces_.cell_pressures(); }

  // Relaxes the positions of the population to equilibrium, starting from its current
  // positions at rest, and writes the final ones to it. The internal forces of the final
  // positions are left in cells.internal_forces().
  StaticEquilibriumReport solve(const StaticEquilibriumOptions& options = {});

  // r = f_int + f_ext at the population's current positions (into residual()); returns
  // max_a |r_a|.
  double compute_residual();
  const NodeVectors& residual() const { return fire_.residual(); }
  // The applied load L [pN]: pull force + ½ Σ_a |f_dead,a|.
  double applied_load() const { return forces_.applied_load(); }
  // p = Σ_a w_a x_a of the pull's weights at the solver's positions (the population's
  // after a solve; zero without a pull).
  std::array<double, 3> pull_vector() const { return forces_.pull_vector(); }
  const Kokkos::View<double*>& fictitious_masses() const { return masses_.masses(); }

 private:
  // Throws std::invalid_argument when the dead loads do not add up to zero.
  void check_dead_loads() const;
  // Relaxations at fixed pressure multipliers λ_c, then λ_c ← p_c, until the volumes hold.
  void relax_holding_volumes(const StaticEquilibriumOptions& options, StaticEquilibriumReport& report);

  Population& cells_;
  BasicRelaxationMasses<ExecSpace> masses_;
  BasicEquilibriumForces<ExecSpace> forces_;
  BasicFireRelaxation<ExecSpace> fire_;
};

using StaticEquilibrium = BasicStaticEquilibrium<Kokkos::DefaultExecutionSpace>;

extern template class BasicStaticEquilibrium<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
