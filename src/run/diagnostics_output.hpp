#pragma once
// The run's diagnostics.csv (io/diagnostics_table.hpp): its columns are the fluid's, then
// the cells' (with cells), then the coupling's (with a coupling), as run/run_diagnostics.hpp
// measures them; a row is measured from the simulation's current step. Every rank measures
// (some measures are sums over the ranks); the first rank writes the file.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/checkpoint_file.hpp"
#include "io/diagnostics_table.hpp"
#include "run/run_diagnostics.hpp"
#include "run/simulation.hpp"

namespace rouleau {

// The rows a restart keeps of the diagnostics.csv in `output_dir`: those up to the step of
// the checkpoint it continues from (what the stopped run wrote after it is dropped). None
// without a `restart`, on the ranks that do not write files, or when the file cannot be
// read (said on stderr).
std::vector<std::map<std::string, double>> earlier_diagnostics_rows(const std::string& output_dir,
                                                                    const FoundCheckpoint* restart,
                                                                    bool writes_files);

class DiagnosticsOutput {
 public:
  // `cell_diagnostics`: made from the cells as placed (their volume drift is measured from
  // there), before a restart moved them. The first rank (`writes_files`) writes
  // OUTPUT_DIR/diagnostics.csv, starting with `earlier_rows`. `simulation` must outlive it.
  DiagnosticsOutput(const Simulation& simulation, CellDiagnostics cell_diagnostics, const std::string& output_dir,
                    const std::vector<std::map<std::string, double>>& earlier_rows, bool writes_files);

  // Measures the row of the simulation's current step and adds it to the table;
  // `wall_seconds`: the run's wall time so far (run/run_clock.hpp).
  void add_row(Simulation& simulation, double wall_seconds);
  // Writes the rows so far to the file (nothing on the other ranks).
  void flush();

 private:
  FluidDiagnostics fluid_;
  CellDiagnostics cells_;
  CouplingDiagnostics coupling_;
  std::unique_ptr<DiagnosticsTable> table_;  // the first rank's
};

}  // namespace rouleau
