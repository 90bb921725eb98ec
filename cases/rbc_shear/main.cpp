// One red blood cell in simple shear: runs cases/rbc_shear/case.toml (or the file given)
// and reports how the cell turned and deformed, and how well its volume was kept.
//   case_rbc_shear [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cstdio>

#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/rbc_shear");
  if (!run.ran) return run.status;
  // What is special to this case: the cell's inclination, deformation and volume.
  const auto last = rouleau::read_last_diagnostics(run.options.output_dir + "/diagnostics.csv");
  std::printf("t = %.4g s: inclination %.2f deg (placed at 45 deg disc axis, i.e. -45 deg major axis), Taylor "
              "deformation %.4f, centroid (%.4f, %.4f, %.4f) um, largest volume change %.3e, elastic energy %.4g "
              "pN um; relative apparent viscosity %.4f\n",
              last.at("time_s"), last.at("cell0_inclination_deg"), last.at("cell0_taylor_deformation"),
              last.at("cell0_centroid_x_um"), last.at("cell0_centroid_y_um"), last.at("cell0_centroid_z_um"),
              last.at("largest_relative_volume_change"), last.at("elastic_energy_pN_um"),
              last.at("relative_apparent_viscosity"));
  return 0;
}
