// A capsule squeezing through a capillary (paper Figs. 16–17): runs cases/capillary/case.toml
// (or the file given) and prints the history of the driving pressure with the capsule's
// position, the data of the paper's Fig. 17, against the plasma's drop at the same flow,
// then the paper's statement as measures against thresholds (check_capillary_passage).
//   case_capillary [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cstdio>

#include "analysis/paper_checks.hpp"
#include "analysis/scene_checks.hpp"
#include "geometry/vessel_profile.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/capillary");
  if (!run.ran) return run.status;
  // What is special to this case: the driving pressure while the capsule moves.
  const auto rows = rouleau::read_diagnostics(run.options.output_dir + "/diagnostics.csv");
  const bool with_capsule = !rows.empty() && rows.front().count("cell0_centroid_x_um");
  std::printf("%10s %12s %12s %14s\n", "time_s", "capsule_x_um", "driving_Pa", "relative_visc");
  for (const auto& row : rows)
    std::printf("%10.5f %12.4f %12.5f %14.5f\n", row.at("time_s"), with_capsule ? row.at("cell0_centroid_x_um") : 0.0,
                row.at("driving_pressure_Pa"), row.at("relative_apparent_viscosity"));
  const rouleau::VesselProfile& profile = run.config.vessel.profile;
  const double entry = profile.inlet_length + profile.contraction_length, exit = entry + profile.throat_length;
  std::printf("capillary from x = %.1f to %.1f um; relative_visc is the drop over Hagen-Poiseuille's summed over the "
              "cross-sections at the same flow rate (the plasma alone: 1.045)\n",
              entry, exit);
  if (!with_capsule) return 0;
  // The paper's statement (Fig. 17), as measures against thresholds.
  const auto c = rouleau::check_capillary_passage(rows, entry, exit);
  using Check = rouleau::CapillaryPassageCheck;
  auto verdict = [](bool met) { return met ? "met" : "NOT MET"; };
  std::printf("driving pressure %.4f Pa at the start, peak %.4f Pa with the capsule at x = %.2f um, %.4f Pa at the end "
              "(capsule at x = %.2f um)\n",
              c.initial_pressure, c.peak_pressure, c.peak_position, c.final_pressure, c.final_position);
  std::printf("check (the pressure rises while the capsule enters and plugs the capillary): rise %.1f %% >= %.0f %%, "
              "peak within a diameter of the capillary: %s\n",
              100.0 * (c.peak_pressure / c.initial_pressure - 1.0), 100.0 * Check::rise_fraction, verdict(c.rose));
  std::printf("check (and falls after it leaves): capsule past x = %.2f um: %s; fallen by %.0f %% of the rise >= %.0f %%: "
              "%s\n",
              exit + 0.5 * c.free_length, c.left ? "yes" : "no",
              c.peak_pressure > c.initial_pressure
                  ? 100.0 * (c.peak_pressure - c.final_pressure) / (c.peak_pressure - c.initial_pressure)
                  : 0.0,
              100.0 * Check::fall_fraction, verdict(c.fell));
  if (c.longest_inside > 0.0)
    std::printf("check (inside, the capsule is longer than its free diameter): longest %.3f um > %.3f um: %s\n",
                c.longest_inside, c.free_length, verdict(c.longer_inside));
  else
    std::printf("check (inside, the capsule is longer than its free diameter): its centroid never entered the "
                "capillary: NOT MET\n");
  if (c.plateau_rows > 0)
    std::printf("check (the pressure stays up while the capsule is wholly inside): %d rows >= %d, spread %.1f %% of "
                "the mean <= %.0f %%, mean %.1f %% above the initial >= %.0f %%: %s\n",
                c.plateau_rows, Check::plateau_rows_min, 100.0 * c.plateau_spread, 100.0 * Check::plateau_spread_max,
                100.0 * (c.plateau_mean / c.initial_pressure - 1.0), 100.0 * Check::rise_fraction, verdict(c.plateau));
  else
    std::printf("check (the pressure stays up while the capsule is wholly inside): it never was wholly inside: "
                "NOT MET\n");
  std::printf("check (it leaves with its rear flared, a jellyfish): largest rear over front radius within a free "
              "length past the exit %.3f >= %.2f: %s\n",
              c.largest_rear_over_front, Check::flare_ratio, verdict(c.flared));
  rouleau::write_paper_checks(run.options.output_dir, rouleau::paper_rows(c, entry, exit));
  return 0;
}
