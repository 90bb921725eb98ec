#pragma once
// What the shear-stack drivers print after a run (cases/stack_shear, paper Figs. 7-11;
// cases/twelve_cells, Fig. 12): each cell's inclination and the neighbour gaps within a
// column over time, then the measures of the paper's statement for the run's shear rate
// (measure_stack, check_stack_statement) and whether they meet its thresholds. Host-only.
#include "analysis/paper_checks.hpp"
#include "analysis/scene_checks.hpp"
#include "config/case_config.hpp"

namespace rouleau {

// The cells placed at the first cell's x form one column (stack); the case file lists the
// columns one after the other, each bottom to top.
int cells_per_column(const CaseConfig& config);

// Prints the report to stdout and returns the rows of the paper's statements it checked
// (Fig. 7 when the diagnostics hold the rims' share, then the stack's statement).
std::vector<PaperCheckRow> print_stack_report(const CaseConfig& config, const DiagnosticsRows& rows);

}  // namespace rouleau
