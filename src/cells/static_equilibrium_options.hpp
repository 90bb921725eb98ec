#pragma once
// What the static equilibrium solve (cells/static_equilibrium.hpp) is asked and what it
// reports: its options (tolerance, FIRE 2.0 parameters, the power iteration's schedule,
// the volume constraint's) and its report.
#include <string>

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

}  // namespace rouleau
