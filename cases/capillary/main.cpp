// A capsule squeezing through a capillary (paper Figs. 16–17): runs cases/capillary/case.toml
// (or the file given) and prints the history of the driving pressure with the capsule's
// position, the data of the paper's Fig. 17, against the plasma's drop at the same flow.
//   case_capillary [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cstdio>

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
  std::printf("capillary from x = %.1f to %.1f um; relative_visc is the drop over Hagen-Poiseuille's summed over the "
              "cross-sections at the same flow rate (the plasma alone: 1.045)\n",
              profile.inlet_length + profile.contraction_length,
              profile.inlet_length + profile.contraction_length + profile.throat_length);
  return 0;
}
