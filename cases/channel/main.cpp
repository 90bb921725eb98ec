// Pressure-driven plane channel: runs cases/channel/case.toml (or the file given) and
// compares the mean velocity with Hagen–Poiseuille, U = Δp H² / (12 μ L).
//   case_channel [CASE.toml] [OUT_DIR]
#include <Kokkos_Core.hpp>
#include <cmath>
#include <cstdio>

#include "config/load_case.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  // Inputs
  const std::string case_file = argc > 1 ? argv[1] : ROULEAU_CASE_DIR "/case.toml";
  rouleau::RunOptions options;
  options.output_dir = argc > 2 ? argv[2] : "runs/channel";
  const rouleau::CaseConfig config = rouleau::load_case(case_file);
  // Run
  const int status = rouleau::run_case(config, options);
  if (status != 0) return status;
  // What is special to this case: the flow rate against Hagen–Poiseuille.
  const auto& d = config.domain;
  const double height = d.upper[1] - d.lower[1], length = d.upper[0] - d.lower[0];
  const double pressure_drop = d.boundary[rouleau::Side::x_min].pressure - d.boundary[rouleau::Side::x_max].pressure;
  const double predicted = pressure_drop * height * height / (12.0 * config.fluid.viscosity * length);
  const double computed = rouleau::read_last_diagnostics(options.output_dir + "/diagnostics.csv")["mean_velocity_x_um_s"];
  std::printf("mean velocity %.4f um/s, Hagen-Poiseuille %.4f um/s, relative difference %.2e\n", computed, predicted,
              std::fabs(computed - predicted) / predicted);
  return 0;
}
