// A stiff sphere on the axis of Poiseuille flow in a tube: runs cases/sphere_in_tube/case.toml
// (or the file given) and compares its speed with Bungay & Brenner's (1973).
//   case_sphere_in_tube [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cmath>
#include <cstdio>

#include "analysis/sphere_in_tube.hpp"
#include "config/cell_kinds.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/sphere_in_tube");
  if (!run.ran) return run.status;
  // What is special to this case: a/R, the tube's mean speed, the sphere's speed after
  // the first half of the run (the start-up).
  const rouleau::CaseConfig& config = run.config;
  const rouleau::CellKindConfig& sphere = *rouleau::find_cell_kind(config, config.cells.at(0).kind);
  const double radius_ratio = 0.5 * sphere.diameter / config.vessel.profile.radius;
  const double mean_speed = config.vessel.inlet.mean_speed;
  const auto rows = rouleau::read_diagnostics(run.options.output_dir + "/diagnostics.csv");
  const rouleau::PlugSpeed plug = rouleau::measure_plug_speed(rows, 0.5 * config.time.end);
  const double reference = rouleau::sphere_in_tube_speed_ratio(radius_ratio);
  const double ratio = plug.speed / mean_speed;
  std::printf("a/R = %.3f: U / V_mean = %.4f (speed %.4f um/s, spread %.2g um/s over %d rows), Bungay & Brenner %.4f "
              "(%+.2f %%): %s (within 10 %%)\n",
              radius_ratio, ratio, plug.speed, plug.speed_spread, plug.rows, reference,
              100.0 * (ratio / reference - 1.0), std::fabs(ratio / reference - 1.0) < 0.1 ? "met" : "NOT MET");
  return 0;
}
