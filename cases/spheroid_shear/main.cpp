// A stiff spheroid tumbling in simple shear: runs cases/spheroid_shear/case.toml (or the
// file given) and compares the turning of its symmetry axis with Jeffery's (1922) orbit.
//   case_spheroid_shear [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cstdio>

#include "analysis/jeffery_orbit.hpp"
#include "analysis/scene_checks.hpp"
#include "config/cell_kinds.hpp"
#include "config/derived.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/spheroid_shear");
  if (!run.ran) return run.status;
  // What is special to this case: the shear rate, the body's axis ratio, its angle.
  const rouleau::CaseConfig& config = run.config;
  const rouleau::CellKindConfig& body = *rouleau::find_cell_kind(config, config.cells.at(0).kind);
  const auto& domain = config.domain;
  const double shear_rate = rouleau::derive_quantities(config).shear_rate;  // the walls' γ̇
  const double h_f = (domain.upper[0] - domain.lower[0]) / domain.elements[0];
  const auto rows = rouleau::read_diagnostics(run.options.output_dir + "/diagnostics.csv");
  const auto times = rouleau::diagnostics_column(rows, "time_s");
  const auto angles =
      rouleau::symmetry_axis_angles(rouleau::diagnostics_column(rows, "cell0_inclination_deg"), body.axis_ratio);
  const rouleau::JefferyComparison jeffery =
      rouleau::compare_with_jeffery(times, angles, body.axis_ratio, shear_rate);
  std::printf("spheroid c/a = %.4g, semi-axes %.3g and %.3g um, h_f = %.3g um, shear rate %.3g /s, dt = %.3g s\n",
              body.axis_ratio, 0.5 * body.diameter, 0.5 * body.diameter * body.axis_ratio, h_f, shear_rate,
              config.time.dt);
  if (jeffery.measured_period > 0.0)
    std::printf("Jeffery period %.4f s, measured %.4f s (%+.2f %%); ", jeffery.jeffery_period, jeffery.measured_period,
                100.0 * jeffery.period_error);
  else
    std::printf("Jeffery period %.4f s, no half turn in the run; ", jeffery.jeffery_period);
  if (jeffery.flip_time > 0.0)
    std::printf("flip 45 -> 135 deg %.4f s (Jeffery %.4f s); ", jeffery.flip_time, jeffery.jeffery_flip_time);
  std::printf("angle RMS %.2f deg (largest %.2f): %s (period within %.0f %%, RMS within %.0f deg)\n",
              jeffery.rms_angle_error_deg, jeffery.largest_angle_error_deg, jeffery.met() ? "met" : "NOT MET",
              100.0 * rouleau::JefferyComparison::period_tolerance, rouleau::JefferyComparison::rms_tolerance_deg);
  return 0;
}
