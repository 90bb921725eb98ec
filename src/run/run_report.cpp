// The lines a run writes about itself at its start and at its end (run/run_report.hpp).
#include "run/run_report.hpp"

#include <Kokkos_Core.hpp>
#include <iostream>
#include <string>
#include <sys/resource.h>

#include "io/run_folder.hpp"
#include "rouleau_version.hpp"
#include "run/thread_binding.hpp"

namespace rouleau {

namespace {
// "2, 1, 0": how many cells each of `ranks` ranks computes.
std::string cells_per_rank(const std::vector<int>& cell_ranks, const int ranks) {
  std::vector<int> count(ranks, 0);
  for (const int r : cell_ranks) ++count[r];
  std::string text;
  for (int r = 0; r < ranks; ++r) text += (r > 0 ? ", " : "") + std::to_string(count[r]);
  return text;
}

// The process's peak resident memory so far (getrusage: kilobytes on Linux).
double peak_resident_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * static_cast<double>(usage.ru_maxrss);
}
}  // namespace

void report_run_opening(const CaseConfig& config, const std::string& output_dir) {
  std::cerr << "rouleau " << ROULEAU_VERSION << " (" << ROULEAU_GIT_HASH << "): run of case " << config.name
            << " into " << output_dir << "\n";
}

void report_run_setup(const Simulation& simulation, const DerivedQuantities& derived, const Communicator& ranks,
                      const MemoryEstimate& memory) {
  const CaseConfig& config = simulation.config();
  const CaseCells& cells = simulation.cells();
  const ImmersedCoupling* coupling = simulation.coupling();
  std::cerr << "fluid mesh: " << simulation.mesh().num_nodes << " nodes, " << simulation.mesh().num_elements << " "
            << (simulation.mesh().element_type == FluidElementType::tetrahedron4 ? "tetrahedra" : "hexahedra") << ", "
            << simulation.fluid().num_global_unknowns() << " unknowns; "
            << Kokkos::DefaultExecutionSpace::name() << " on " << Kokkos::DefaultHostExecutionSpace().concurrency()
            << " host threads" << (ranks.size() > 1 ? " per rank, " + std::to_string(ranks.size()) + " MPI ranks" : "")
            << "\n";
  std::cerr << "memory: about " << format_bytes(memory.total_bytes) << " estimated (largest part: "
            << memory.terms.front().first << ")\n";
  if (const std::string threads = describe_host_thread_binding(Kokkos::DefaultHostExecutionSpace().concurrency());
      !threads.empty())
    std::cerr << threads << "\n";
  if (const FluidDistribution* distribution = simulation.distribution())
    std::cerr << "fluid split across " << ranks.size() << " ranks: rank 0 owns "
              << distribution->partition().elements.size() << " elements and "
              << distribution->partition().num_owned_nodes << " of its " << distribution->partition().num_local_nodes()
              << " nodes" << (cells.population ? "; every rank holds every cell" : "") << "\n";
  if (!simulation.cell_ranks().empty())
    std::cerr << "cells computed by the rank holding their centroid; per rank: "
              << cells_per_rank(simulation.cell_ranks(), ranks.size()) << "\n";
  const int cell_count = static_cast<int>(config.cells.size());
  if (cell_count > config.output.cell_gaps_max_cells && cell_count > 1)
    std::cerr << "cell gaps: not in the diagnostics (" << cell_count << " cells, more than output.cell_gaps_max_cells = "
              << config.output.cell_gaps_max_cells << ")\n";
  if (coupling && !derived.accuracy_warning.empty()) std::cerr << "warning: " << derived.accuracy_warning << "\n";
  if (coupling && coupling->semi_implicit())
    std::cerr << "semi-implicit coupling: dt = " << config.time.dt << " s (the explicit stable step estimate, "
              << derived.stable_dt << " s, does not bind it)\n";
  else if (coupling)
    std::cerr << "explicit coupling: dt = " << config.time.dt << " s, stable step estimate " << derived.stable_dt
              << " s (" << derived.stable_dt_reason << ")"
              << (config.time.dt > derived.stable_dt ? "; ABOVE IT (coupling.allow_unstable_step = true)" : "")
              << "\n";
}

void report_run_end(const Simulation& simulation, const Communicator& ranks, const double wall_seconds,
                    const MemoryEstimate& memory, const std::string& output_dir,
                    const std::vector<std::string>& field_xdmf_paths) {
  const bool transient = simulation.config().time.mode == TimeMode::transient;
  const bool fields = !field_xdmf_paths.empty();
  if (!simulation.cell_ranks().empty())
    std::cerr << "cells changed rank " << simulation.cell_rank_changes() << " times in this run; per rank now: "
              << cells_per_rank(simulation.cell_ranks(), ranks.size()) << "\n";
  simulation.times().print(std::cerr, wall_seconds);
  std::cerr << "peak memory: " << format_bytes(peak_resident_bytes()) << " (estimated " << format_bytes(memory.total_bytes)
            << ")\n";
  std::cerr << "wrote " << output_dir << "/" << (fields ? "fields*.xdmf, " : "") << "diagnostics.csv, case.resolved.toml, "
            << run_log_name << (transient ? ", checkpoints/" : "") << "\n";
  if (fields) {
    std::cerr << "ParaView: open";
    for (const std::string& path : field_xdmf_paths) std::cerr << " " << path;
    std::cerr << " (reader Xdmf3ReaderT; docs/paraview.md)\n";
  }
  std::cerr << "figures: scripts/plot_diagnostics.py " << output_dir << "\n";
}

}  // namespace rouleau
