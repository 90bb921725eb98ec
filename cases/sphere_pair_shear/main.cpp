// Two stiff spheres passing each other in simple shear: runs cases/sphere_pair_shear/case.toml
// (or the file given) and measures how far their offset across the streamlines changed.
//   case_sphere_pair_shear [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cstdio>

#include "analysis/pair_reversibility.hpp"
#include "config/cell_kinds.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/sphere_pair_shear");
  if (!run.ran) return run.status;
  // What is special to this case: the offset before and after, over the radius.
  const rouleau::CaseConfig& config = run.config;
  const rouleau::CellKindConfig& sphere = *rouleau::find_cell_kind(config, config.cells.at(0).kind);
  const double radius = 0.5 * sphere.diameter;
  const double h_f = (config.domain.upper[0] - config.domain.lower[0]) / config.domain.elements[0];
  const auto rows = rouleau::read_diagnostics(run.options.output_dir + "/diagnostics.csv");
  const rouleau::PairReversibility pair = rouleau::measure_pair_reversibility(rows, radius);
  if (!pair.passed) {
    std::printf("a/h_f = %.3g: the spheres did not get as far past each other as they started apart: no measure\n",
                radius / h_f);
    return 0;
  }
  std::printf("a/h_f = %.3g: offset across the streamlines %.4f um, and %.4f um as far past (t = %.3f s): asymmetry "
              "(after - before) / a = %+.4f (0 for smooth spheres in Stokes flow); smallest gap %.4f um (%.3g a)\n",
              radius / h_f, pair.initial_offset, pair.final_offset, pair.symmetric_time, pair.asymmetry,
              pair.smallest_gap, pair.smallest_gap / radius);
  return 0;
}
