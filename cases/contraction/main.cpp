// Plasma through a micro-vessel contraction: runs cases/contraction/case.toml (or the file
// given) and sets the driving pressure against Hagen–Poiseuille's drop summed over the
// cross-sections, (8 μ Q / π) ∫ dx / R(x)⁴, and the outflow against the inflow.
//   case_contraction [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <Kokkos_Core.hpp>
#include <cmath>
#include <cstdio>

#include "geometry/vessel_profile.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/contraction");
  if (!run.ran) return run.status;
  // What is special to this case: the pressure the contraction costs, and mass balance.
  const auto last = rouleau::read_last_diagnostics(run.options.output_dir + "/diagnostics.csv");
  const double inflow = last.at("flow_rate_inlet_um3_s"), outflow = last.at("flow_rate_outlet_um3_s");
  const double drop = last.at("driving_pressure_Pa");
  const double lubrication = rouleau::vessel_poiseuille_drop(run.config.vessel.profile, run.config.fluid.viscosity, outflow);
  std::printf("flow rate in %.4f, out %.4f um^3/s (relative difference %.1e)\n", inflow, outflow,
              std::fabs(outflow - inflow) / inflow);
  std::printf("driving pressure %.5f Pa; Hagen-Poiseuille summed over the cross-sections %.5f Pa; ratio %.4f "
              "(the entrance and exit losses)\n",
              drop, lubrication, drop / lubrication);
  return 0;
}
