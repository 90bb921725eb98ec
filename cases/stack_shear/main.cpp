// A stack of red cells in simple shear (paper Figs. 7-11): runs cases/stack_shear/case.toml
// (or the file given), prints each cell's inclination and the neighbour gaps over time,
// then the measures of the paper's statement for the run's shear rate and whether they
// meet its thresholds (src/analysis/stack_report.hpp).
//   case_stack_shear [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include "analysis/paper_checks.hpp"
#include "analysis/stack_report.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/stack_shear");
  if (!run.ran) return run.status;
  // What is special to this case: the stack's shape over time and the paper's statement.
  const auto rows = rouleau::read_diagnostics(run.options.output_dir + "/diagnostics.csv");
  rouleau::write_paper_checks(run.options.output_dir, rouleau::print_stack_report(run.config, rows));
  return 0;
}
