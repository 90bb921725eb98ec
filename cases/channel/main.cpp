// Pressure-driven plane channel: runs cases/channel/case.toml (or the file given) and
// compares the mean velocity with Hagen–Poiseuille, U = Δp H² / (12 μ L).
//   case_channel [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cmath>
#include <cstdio>

#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/channel");
  if (!run.ran) return run.status;
  // What is special to this case: the flow rate against Hagen–Poiseuille.
  const auto& d = run.config.domain;
  const double height = d.upper[1] - d.lower[1], length = d.upper[0] - d.lower[0];
  const double pressure_drop = d.boundary[rouleau::Side::x_min].pressure - d.boundary[rouleau::Side::x_max].pressure;
  const double predicted = pressure_drop * height * height / (12.0 * run.config.fluid.viscosity * length);
  const double computed =
      rouleau::read_last_diagnostics(run.options.output_dir + "/diagnostics.csv").at("mean_velocity_x_um_s");
  std::printf("mean velocity %.4f um/s, Hagen-Poiseuille %.4f um/s, relative difference %.2e\n", computed, predicted,
              std::fabs(computed - predicted) / predicted);
  return 0;
}
