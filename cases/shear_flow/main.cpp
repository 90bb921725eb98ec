// Simple shear of plasma between moving walls: runs cases/shear_flow/case.toml (or the file
// given) and checks that plasma alone has a relative apparent viscosity of 1 (wall shear
// stress τ_w = μ γ̇). The four-cell cases fill this box with cells.
//   case_shear_flow [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cstdio>

#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/shear_flow");
  if (!run.ran) return run.status;
  // What is special to this case: the suspension's rheology (here plasma alone).
  const auto last = rouleau::read_last_diagnostics(run.options.output_dir + "/diagnostics.csv");
  std::printf("wall shear stress %.6g Pa (top), %.6g Pa (bottom); relative apparent viscosity %.6f\n",
              last.at("wall_shear_stress_y_max_Pa"), last.at("wall_shear_stress_y_min_Pa"),
              last.at("relative_apparent_viscosity"));
  return 0;
}
