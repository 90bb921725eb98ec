// Twelve red cells aggregated in simple shear at 3.0 1/s (paper Fig. 12): runs
// cases/twelve_cells/case.toml (or the file given), prints each cell's inclination and the
// neighbour gaps within each of the three columns over time, then the measures of the
// paper's statement (rotation, partial break-up, layers) against its thresholds
// (src/analysis/stack_report.hpp, as for the four-cell stack).
//   case_twelve_cells [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include "analysis/paper_checks.hpp"
#include "analysis/stack_report.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/twelve_cells");
  if (!run.ran) return run.status;
  // What is special to this case: the aggregate's shape over time and the paper's statement.
  const auto rows = rouleau::read_diagnostics(run.options.output_dir + "/diagnostics.csv");
  rouleau::write_paper_checks(run.options.output_dir, rouleau::print_stack_report(run.config, rows));
  return 0;
}
