#pragma once
// The readers of a case file's tables, each filling its part of a CaseConfig from the
// document's root table (internal to load_case(); the order they run in is load_case.cpp's).
// Host-only: includes no Kokkos header.
#include <optional>
#include <string>

#include "config/case_config.hpp"
#include "config/toml_table_reader.hpp"

namespace rouleau {

// ---- the run's settings (read_settings.cpp)
void read_case_section(const TableReader& root, const std::string& path, CaseConfig& config);
void read_fluid(const TableReader& root, FluidConfig& fluid);
void read_time(const TableReader& root, TimeConfig& time);
void read_solver(const TableReader& root, SolverConfig& solver);
void read_scales(const TableReader& root, ScalesConfig& scales);
void read_output(const TableReader& root, OutputConfig& output);
void read_checkpoint(const TableReader& root, CheckpointConfig& checkpoint);
// `interaction`: read before, for the checks that combine both sections.
void read_coupling(const TableReader& root, CouplingConfig& coupling, const InteractionConfig& interaction);
void read_scene(const TableReader& root, SceneConfig& scene);
// The key density_kg_m3 of a table ([fluid], [cell_kinds.NAME]), converted to pN·s²/μm⁴.
std::optional<double> read_density(const TableReader& section);
// The explicit coupling refuses a step above its stable estimate unless asked to force it
// (the semi-implicit coupling is not bound by it): InputError at time.dt_s.
void check_time_step(const CaseConfig& config);
// solver.preconditioner = "fast_diagonalization" where it does not apply (it needs a
// uniform box periodic along two axes, Stokes) is refused.
void check_preconditioner(const CaseConfig& config);

// ---- the fluid domain (read_domain.cpp): a box, or a vessel
void read_domain(const TableReader& root, DomainConfig& domain);
void read_boundaries(const TableReader& root, DomainConfig& domain);
void read_vessel(const TableReader& root, VesselConfig& vessel);
void read_vessel_boundaries(const TableReader& root, VesselConfig& vessel);

// ---- the cells (read_cells.cpp)
void read_cell_kinds(const TableReader& root, std::vector<CellKindConfig>& kinds);
void read_cells(const TableReader& root, CaseConfig& config);
void read_interaction(const TableReader& root, CaseConfig& config);

}  // namespace rouleau
