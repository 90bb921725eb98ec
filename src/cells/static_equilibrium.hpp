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
// λ_c ← p_c and relax again, until |V_c − V0_c| ≤ volume_tolerance · V0_c.
#include <Kokkos_Core.hpp>
#include <array>
#include <string>
#include <vector>

#include "cells/cell_population.hpp"

namespace rouleau {

struct StaticEquilibriumOptions {
  // Converged when the largest nodal residual max_a |f_int,a + f_ext,a| is at most
  // relative_tolerance times the applied load (at least load_floor).
  double relative_tolerance = 1e-5;
  double load_floor = 1.0;  // [pN]
  int max_iterations = 200000;
  // The largest nodal residual is reduced every check_interval iterations.
  int check_interval = 10;
  // FIRE 2.0 parameters (Guénolé et al. 2020, Table 1). The largest step is
  // step_fraction times the linear stability limit 2/√λ_max of the mass-scaled
  // stiffness; the first step is a tenth of it, the smallest a fiftieth of that.
  double step_fraction = 0.5;
  int delay_steps = 20;
  double step_increase = 1.1;
  double step_decrease = 0.5;
  double alpha_start = 0.25;
  double alpha_decrease = 0.99;
  int max_uphill_steps = 2000;
  // Power iterations for λ_max (Rayleigh quotient; the step limit is then
  // safety-checked by FIRE's own uphill detection): power_iterations at the start, then
  // every eigenvalue_interval FIRE steps update_power_iterations more, warm-started, so
  // that the step limit follows the stiffening of the deformed cell.
  int power_iterations = 30;
  int eigenvalue_interval = 500;
  int update_power_iterations = 5;
  // The largest distance a node may move in one step [μm].
  double max_step_length = 0.05;
  // Enclosed-volume constraint (when set_volume_constraint() was called): relative volume
  // tolerance and the most augmented-Lagrangian updates.
  double volume_tolerance = 1e-4;
  int max_volume_updates = 30;
};

struct StaticEquilibriumReport {
  bool converged = false;
  int iterations = 0;                 // FIRE steps
  int force_evaluations = 0;          // internal-force evaluations, power iteration included
  double max_residual = 0.0;          // [pN] max_a |f_int,a + f_ext,a| at the end
  double tolerance = 0.0;             // [pN] the one it was held to
  double applied_load = 0.0;          // [pN] L
  double largest_eigenvalue = 0.0;    // last λ_max estimate of M^(−1/2) K M^(−1/2) [pN/μm²]
  double final_step = 0.0;            // Δt at the end (mass-scaled units)
  double strain_energy = 0.0;         // W at the end (strain energy + area term) [pN·μm]
  double seconds = 0.0;               // wall time of the solve
  std::string stop_reason;            // "converged", "max_iterations", "uphill", "not finite",
                                      // "volume" (the volume constraint did not converge)
  int volume_updates = 0;             // augmented-Lagrangian updates (volume constraint)
  double largest_volume_error = 0.0;  // max_c |V_c − V0_c| / V0_c at the end
  double largest_pressure = 0.0;      // max_c |p_c| at the end [Pa]
};

template <class ExecSpace>
class BasicStaticEquilibrium {
 public:
  using Population = BasicCellPopulation<ExecSpace>;
  using NodeVectors = typename Population::NodeVectors;

  // Works on `cells` in place (the population must outlive the solver). Fictitious
  // masses are computed here, once, from the reference configuration.
  explicit BasicStaticEquilibrium(Population& cells);

  // Dead loads f_dead (node, 3) [pN], zero at construction: fill the View. They must add
  // up to zero (solve() throws std::invalid_argument otherwise).
  const NodeVectors& dead_loads() const { return dead_loads_; }

  // A pull of magnitude `force` [pN] between two node groups along the line through their
  // weighted centres: w_a > 0 on one group (summing to 1), w_a < 0 on the other (summing
  // to −1), 0 elsewhere. With p = Σ_a w_a x_a (the vector from the negative group's centre
  // to the positive one's), f_ext,a = F w_a p/|p| = −∂Π_ext/∂x_a with Π_ext = −F |p|.
  void set_pull(const Kokkos::View<double*>& signed_weights, double force);
  void clear_pull() { pull_force_ = 0.0; }
  double pull_force() const { return pull_force_; }

  // Holds every cell's enclosed volume at its value in the reference configuration by an
  // internal pressure (augmented Lagrangian with penalty `stiffness` k [pN/μm⁵]); k = 0
  // turns the constraint off. The pressures start at zero.
  void set_volume_constraint(double stiffness);
  // The cells' internal pressures p_c [Pa] (zero without the constraint).
  const std::vector<double>& cell_pressures() const { return cell_pressures_; }

  // Relaxes the positions of the population to equilibrium, starting from the current
  // positions at rest. The internal forces of the final positions are left in
  // cells.internal_forces().
  StaticEquilibriumReport solve(const StaticEquilibriumOptions& options = {});

  // r = f_int + f_ext at the current positions (into residual()); returns max_a |r_a|.
  double compute_residual();
  const NodeVectors& residual() const { return residual_; }
  // The applied load L [pN]: pull force + ½ Σ_a |f_dead,a|.
  double applied_load() const;
  // p = Σ_a w_a x_a of the pull's weights at the current positions (zero without a pull).
  std::array<double, 3> pull_vector() const;
  const Kokkos::View<double*>& fictitious_masses() const { return mass_; }

  // ---- the device kernels (public: CUDA lambdas may not live in private members)
  void compute_masses();
  // Internal forces (into cells.internal_forces()) and, with the volume constraint, the
  // pressure forces (into constraint_forces_) at the current positions.
  void evaluate_forces();
  // out = f_int + f_pressure.
  void conservative_forces(const NodeVectors& out) const;
  // The largest node displacement Δt |u_a|/√m_a the next FIRE move would make.
  double largest_move(bool uphill, double step, double alpha, double mix) const;
  // r = f_int + f_ext with the pull along p; returns {P = Σ u·g, Σ u·u, Σ g·g}, g = M^(−1/2) r.
  std::array<double, 3> residual_and_power(const std::array<double, 3>& p);
  double largest_residual() const;
  // One FIRE move (see the .cpp); returns the pull vector p at the new positions.
  std::array<double, 3> fire_move(bool uphill, double step, double alpha, double mix, double scale);
  // λ_max of M^(−1/2) K M^(−1/2) at the current positions by power iteration, from a
  // pseudo-random start or (warm_start) from the last iterate. Positions and internal
  // forces are restored.
  double estimate_largest_eigenvalue(int iterations, bool warm_start, int& force_evaluations);

 private:
  // One FIRE relaxation at fixed pressure multipliers (solve() without the volume loop).
  void relax(const StaticEquilibriumOptions& options, StaticEquilibriumReport& report);

  Population& cells_;
  Kokkos::View<double*> mass_, inverse_sqrt_mass_, pull_weights_, device_cell_pressures_;
  NodeVectors dead_loads_, residual_, scaled_velocity_, scratch_a_, scratch_b_, constraint_forces_;
  double pull_force_ = 0.0;
  double volume_stiffness_ = 0.0;
  std::vector<double> reference_volumes_, volume_multipliers_, cell_pressures_, cell_volumes_;
};

using StaticEquilibrium = BasicStaticEquilibrium<Kokkos::DefaultExecutionSpace>;

// ---- the optical-tweezers stretch (Mills et al. 2004; Dao, Lim & Suresh 2003)

// Diameters of a stretched cell, measured like Mills et al. on the video images: the
// axial one along the pull, the transverse one across it in the plane of the disc.
struct StretchDiameters {
  double axial = 0.0;       // largest extent along the pull direction [μm]
  double transverse = 0.0;  // largest extent along the in-plane perpendicular [μm]
  std::array<double, 3> pull_direction{1.0, 0.0, 0.0};
};

// The two contact patches of a cell held at opposite ends (the silica beads of the
// experiment, contact diameter d_c = 2 μm): the outer-surface nodes within d_c/2 of the
// two points where the line through the cell's centroid along `direction` leaves the
// cell's nodes (the extreme node projections). The weights are the reference area weights
// normalised per patch (+ at the end along `direction`, − at the other), so a pull spreads
// the force as a uniform traction F/A_patch over each patch.
template <class ExecSpace>
class BasicStretchPatches {
 public:
  BasicStretchPatches(const BasicCellPopulation<ExecSpace>& cells, int cell, std::array<double, 3> direction,
                      std::array<double, 3> in_plane_transverse, double contact_diameter = 2.0);

  const Kokkos::View<double*>& signed_weights() const { return signed_weights_; }
  int node_count(int side) const { return side > 0 ? positive_nodes_ : negative_nodes_; }
  double patch_area(int side) const { return side > 0 ? positive_area_ : negative_area_; }
  int cell_surface_nodes() const { return surface_nodes_; }

  // Axial diameter along the current pull direction p/|p| (p = Σ w_a x_a), transverse
  // diameter along the in-plane transverse direction made perpendicular to it, both over
  // the cell's nodes at the current positions.
  StretchDiameters diameters(const BasicCellPopulation<ExecSpace>& cells) const;

 private:
  int cell_ = 0;
  std::array<double, 3> transverse_{0.0, 1.0, 0.0};
  Kokkos::View<double*> signed_weights_;
  int positive_nodes_ = 0, negative_nodes_ = 0, surface_nodes_ = 0;
  double positive_area_ = 0.0, negative_area_ = 0.0;
};

using StretchPatches = BasicStretchPatches<Kokkos::DefaultExecutionSpace>;

extern template class BasicStaticEquilibrium<Kokkos::DefaultExecutionSpace>;
extern template class BasicStretchPatches<Kokkos::DefaultExecutionSpace>;

}  // namespace rouleau
