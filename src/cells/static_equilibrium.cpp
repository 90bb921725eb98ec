// The static equilibrium solve (cells/static_equilibrium.hpp): its checks, the volume
// constraint's augmented-Lagrangian loop around the FIRE relaxation, and the one write of
// the final positions to the population.
#include "cells/static_equilibrium.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "util/instantiate.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

template <class ExecSpace>
BasicStaticEquilibrium<ExecSpace>::BasicStaticEquilibrium(Population& cells)
    : cells_(cells), masses_(cells), forces_(cells), fire_(forces_, masses_) {}

template <class ExecSpace>
void BasicStaticEquilibrium<ExecSpace>::check_dead_loads() const {
  // Dead loads must be balanced, or the body accelerates away and no equilibrium exists.
  const std::array<double, 3> sums = forces_.dead_load_sum();
  const double magnitude = forces_.applied_load() - forces_.pull_force();
  const double net = std::sqrt(sums[0] * sums[0] + sums[1] * sums[1] + sums[2] * sums[2]);
  if (net > 0.0 && net > 1e-9 * magnitude) {
    std::ostringstream msg;
    msg << "rouleau::StaticEquilibrium::solve: the dead loads add up to " << net << " pN (of " << 2 * magnitude
        << " pN in all): unbalanced loads have no static equilibrium";
    throw std::invalid_argument(msg.str());
  }
}

template <class ExecSpace>
StaticEquilibriumReport BasicStaticEquilibrium<ExecSpace>::solve(const StaticEquilibriumOptions& options) {
  ProfilingRegion region("rouleau::StaticEquilibrium::solve");
  const auto start = std::chrono::steady_clock::now();
  StaticEquilibriumReport report;
  check_dead_loads();
  report.applied_load = forces_.applied_load();
  report.tolerance = options.relative_tolerance * std::max(report.applied_load, options.load_floor);

  forces_.start_from(cells_.positions());
  if (forces_.holds_volumes())
    relax_holding_volumes(options, report);
  else
    fire_.relax(options, report);
  // The population's one write: the final positions, then their forces and energy.
  cells_.set_positions(forces_.positions());
  report.strain_energy = cells_.compute_internal_forces_and_energy();
  ++report.force_evaluations;
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

template <class ExecSpace>
void BasicStaticEquilibrium<ExecSpace>::relax_holding_volumes(const StaticEquilibriumOptions& options,
                                                              StaticEquilibriumReport& report) {
  // Augmented Lagrangian: relax at fixed multipliers λ_c, then λ_c ← p_c.
  for (;;) {
    fire_.relax(options, report);
    report.largest_volume_error = forces_.largest_volume_error();
    if (!report.converged || report.largest_volume_error <= options.volume_tolerance) break;
    if (report.volume_updates >= options.max_volume_updates) {
      report.converged = false;
      report.stop_reason = "volume";
      break;
    }
    forces_.update_volume_multipliers();
    ++report.volume_updates;
  }
  for (const double p : forces_.cell_pressures())
    report.largest_pressure = std::max(report.largest_pressure, std::fabs(p));
}

template <class ExecSpace>
double BasicStaticEquilibrium<ExecSpace>::compute_residual() {
  forces_.start_from(cells_.positions());
  forces_.evaluate();
  fire_.residual_and_power(forces_.pull_vector());
  return fire_.largest_residual();
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicStaticEquilibrium)

}  // namespace rouleau
