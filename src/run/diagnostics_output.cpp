// The run's diagnostics.csv: the rows a restart keeps, the columns, and one measured row
// per call (run/diagnostics_output.hpp).
#include "run/diagnostics_output.hpp"

#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "io/diagnostics_reader.hpp"

namespace rouleau {

namespace {
// The rows of an earlier segment's diagnostics.csv; none when it cannot be read (it holds
// only its header, or was damaged by hand: said on stderr).
std::vector<std::map<std::string, double>> read_diagnostics_rows(const std::string& path) {
  try {
    return read_diagnostics(path);
  } catch (const std::runtime_error& error) {
    std::cerr << "rouleau: the earlier diagnostics are not carried over: " << error.what() << "\n";
    return {};
  }
}
}  // namespace

std::vector<std::map<std::string, double>> earlier_diagnostics_rows(const std::string& output_dir,
                                                                    const FoundCheckpoint* restart,
                                                                    const bool writes_files) {
  const std::string path = output_dir + "/diagnostics.csv";
  std::vector<std::map<std::string, double>> rows;
  if (writes_files && restart && std::filesystem::exists(path))
    for (auto& row : read_diagnostics_rows(path))
      if (row.count("step") && row["step"] <= restart->data.step) rows.push_back(std::move(row));
  return rows;
}

DiagnosticsOutput::DiagnosticsOutput(const Simulation& simulation, CellDiagnostics cell_diagnostics,
                                     const std::string& output_dir,
                                     const std::vector<std::map<std::string, double>>& earlier_rows,
                                     const bool writes_files)
    : fluid_(simulation.config(), simulation.mesh()), cells_(std::move(cell_diagnostics)) {
  std::vector<std::string> columns = fluid_.columns();
  if (simulation.cells().population) {
    const auto cell_columns = cells_.columns();
    columns.insert(columns.end(), cell_columns.begin(), cell_columns.end());
  }
  if (simulation.coupling()) {
    const auto coupling_columns = coupling_.columns();
    columns.insert(columns.end(), coupling_columns.begin(), coupling_columns.end());
  }
  if (writes_files) table_ = std::make_unique<DiagnosticsTable>(output_dir + "/diagnostics.csv", columns, earlier_rows);
}

void DiagnosticsOutput::add_row(Simulation& simulation, const double wall_seconds) {
  const ImmersedCoupling* coupling = simulation.coupling();
  std::vector<double> row = fluid_.row(simulation.fluid(), simulation.steps(), simulation.last_report().fluid,
                                       wall_seconds, coupling ? coupling->state().felt_terms : ImmersedTerms{});
  const CaseCells& cells = simulation.cells();
  if (cells.population) {
    const CellForceState& forces = simulation.cell_forces(true);
    const std::vector<double> cell_row =
        simulation.times().time("cell diagnostics", [&] { return cells_.row(cells, forces); });
    row.insert(row.end(), cell_row.begin(), cell_row.end());
  }
  if (coupling) {
    const std::vector<double> coupling_row = coupling_.row(simulation.last_report(), simulation.times());
    row.insert(row.end(), coupling_row.begin(), coupling_row.end());
  }
  if (table_) table_->add_row(row);
}

void DiagnosticsOutput::flush() {
  if (table_) table_->flush();
}

}  // namespace rouleau
