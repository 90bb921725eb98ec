#pragma once
// What a run says about itself on its log (stderr, and run.log through io/run_log.hpp):
// at its start, what runs and how (the version, the case, the mesh and its unknowns, the
// execution space and threads, the memory estimate, the split across ranks, the coupling's
// time step); at its end, what it cost and what it wrote (the stage times, the peak memory,
// the files and how to view them).
#include <string>
#include <vector>

#include "config/case_config.hpp"
#include "config/derived.hpp"
#include "config/memory_estimate.hpp"
#include "parallel/communicator.hpp"
#include "run/simulation.hpp"

namespace rouleau {

// The log's first line: the version, the case and the output folder (before any work).
void report_run_opening(const CaseConfig& config, const std::string& output_dir);

// What the built `simulation` is and how it runs: the fluid mesh and unknowns, the
// execution space and threads (and whether they are bound to cores), `memory`, the fluid's
// split and the cells' share across `ranks`, cell gaps left out of the diagnostics, and
// the coupling with its time step against the stable step estimate.
void report_run_setup(const Simulation& simulation, const DerivedQuantities& derived, const Communicator& ranks,
                      const MemoryEstimate& memory);

// The end of a run that ran to its end: how often cells changed rank, the stage times
// against `wall_seconds`, the peak memory against `memory`, the files written into
// `output_dir` and, when fields were written (`field_xdmf_paths`, one per mesh), the
// files to open in ParaView.
void report_run_end(const Simulation& simulation, const Communicator& ranks, double wall_seconds,
                    const MemoryEstimate& memory, const std::string& output_dir,
                    const std::vector<std::string>& field_xdmf_paths);

}  // namespace rouleau
