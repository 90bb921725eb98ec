// A stack of red cells in simple shear (paper Figs. 7-12): runs cases/stack_shear/case.toml
// (or the file given: cases/stack_shear/twelve_cells.toml for Fig. 12), prints each cell's
// inclination and the neighbour gaps over time, then the measures of the paper's statement
// for the run's shear rate and whether they meet its thresholds.
//   case_stack_shear [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/scene_checks.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/stack_shear");
  if (!run.ran) return run.status;
  // What is special to this case: the stack's shape over time.
  const auto rows = rouleau::read_diagnostics(run.options.output_dir + "/diagnostics.csv");
  const int cells = static_cast<int>(run.config.cells.size());
  // Columns: the cells placed at the first cell's x, in the case file's order.
  int cells_per_stack = 0;
  for (const auto& cell : run.config.cells)
    if (std::fabs(cell.center[0] - run.config.cells.front().center[0]) < 0.5) ++cells_per_stack;
  std::printf("%9s", "time_s");
  for (int c = 0; c < cells; ++c) std::printf("  incl%-3d", c);
  for (int c = 0; c + 1 < cells; ++c)
    if ((c + 1) % cells_per_stack != 0) std::printf("  gap%d_%-3d", c, c + 1);
  std::printf("\n");
  for (const auto& row : rows) {
    std::printf("%9.4f", row.at("time_s"));
    for (int c = 0; c < cells; ++c) std::printf(" %8.2f", row.at("cell" + std::to_string(c) + "_inclination_deg"));
    for (int c = 0; c + 1 < cells; ++c)
      if ((c + 1) % cells_per_stack != 0)
        std::printf(" %9.4f", row.at("gap_" + std::to_string(c) + "_" + std::to_string(c + 1) + "_um"));
    std::printf("\n");
  }
  // The shear rate from the walls: (u_top − u_bottom) / H.
  const auto& domain = run.config.domain;
  const double shear_rate =
      (domain.boundary[rouleau::Side::y_max].velocity[0] - domain.boundary[rouleau::Side::y_min].velocity[0]) /
      (domain.upper[1] - domain.lower[1]);
  const double r0 = run.config.interaction.morse.zero_force_length;
  const rouleau::StackMeasures m = rouleau::measure_stack(rows, cells, cells_per_stack, r0);
  std::printf("shear rate %.3g 1/s, t = %.4g s (strain %.3g): largest neighbour gap growth %.4f um, largest change "
              "of a vertical separation %.4f um, mean inclination %.2f deg (spread %.2f), stack axis %.2f deg, %s\n",
              shear_rate, rows.back().at("time_s"), shear_rate * rows.back().at("time_s"), m.largest_gap_growth,
              m.largest_separation_change, m.mean_inclination_deg, m.inclination_spread_deg, m.stack_axis_deg,
              m.intact ? "intact" : "broken up");
  // The paper's statement for this run, as measures against thresholds.
  const auto check = rouleau::check_stack_statement(m, shear_rate, run.config.interaction.enabled, r0);
  std::printf("check (%s): %s: %s\n", check.statement.c_str(), check.measured.c_str(), check.met ? "met" : "NOT MET");
  return 0;
}
