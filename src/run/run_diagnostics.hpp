#pragma once
// The columns of diagnostics.csv and how each row is measured: the fluid (solver effort,
// residuals, mean velocity, kinetic energy, wall shear stress and the relative apparent
// viscosity), the cells (energies, volumes and their drift, centroids, inclination and
// Taylor deformation in the shear plane) and the coupling
// (power spread and interpolated, speeds, time per stage since the previous row).
#include <memory>
#include <string>
#include <vector>

#include "cells/cell_gaps.hpp"
#include "cells/rim_band.hpp"
#include "cells/cells_from_case.hpp"
#include "config/case_config.hpp"
#include "coupling/immersed_coupling.hpp"
#include "fluid/flow_rates.hpp"
#include "fluid/fluid_solver.hpp"
#include "parallel/communicator.hpp"
#include "util/stage_times.hpp"

namespace rouleau {

// Shear boxes: the wall shear stress on the y walls and the relative apparent viscosity
// τ_w / (μ γ̇). Vessels: the flow rates through inlet and outlet, the driving pressure (the
// mean pressure on the inlet less that on the outlet, the paper's Fig. 17), the mean wall
// shear stress F_x / A_wall, and the relative apparent viscosity Δp / Δp_HP(Q) against
// Hagen–Poiseuille's drop for the outflow Q (vessel_poiseuille_drop(): 1 for plasma in a
// tube; a contraction's cell-free run gives its plasma value).
class FluidDiagnostics {
 public:
  // `config` and `mesh` must outlive it; a vessel's boundary areas are computed here, once.
  FluidDiagnostics(const CaseConfig& config, const FluidMesh& mesh);
  std::vector<std::string> columns() const;
  // `wall_time`: seconds since the run started. `immersed`: the cells' forces the fluid felt
  // over the step (ImmersedCoupling::fluid_terms()), for the walls' reactions; none without
  // cells.
  std::vector<double> row(FluidSolver& solver, int step, const FluidSolveReport& report, double wall_time,
                          const ImmersedTerms& immersed = {}) const;

 private:
  std::vector<double> vessel_row(FluidSolver& solver, const ImmersedTerms& immersed) const;
  std::vector<double> shear_box_row(FluidSolver& solver, const ImmersedTerms& immersed) const;

  const CaseConfig& config_;
  std::unique_ptr<BoundaryIntegrals> boundary_integrals_;  // vessels
};

// The energies are those the step computed at the current positions (CellForces).
// With two cells or more (and at most output.cell_gaps_max_cells), each pair's gap and
// contact area (cells/cell_gaps.hpp; contact: closer than the Morse law's zero-force
// length r0). With the interaction, the share of the Morse forces' magnitude that acts in
// the cells' rim bands and the bands' share of the surface (cells/rim_band.hpp; the
// paper's Fig. 7).
class CellDiagnostics {
 public:
  // `ranks`: when the cells' work is shared across them (CellPopulation::share_work), the
  // energies are summed over the ranks; null on one rank.
  CellDiagnostics(const CaseCells& cells, const CaseConfig& config, const Communicator* ranks = nullptr);
  std::vector<std::string> columns() const;
  std::vector<double> row(const CaseCells& cells, const CellForceState& forces) const;

 private:
  std::vector<double> initial_volumes_;
  std::unique_ptr<CellGaps> gaps_;
  std::unique_ptr<RimBand> rim_band_;
  const Communicator* ranks_;
};

class CouplingDiagnostics {
 public:
  std::vector<std::string> columns() const;
  // The step's report and the stage times; times are those spent since the previous row.
  std::vector<double> row(const ImmersedCoupling::StepReport& report, const StageTimes& times);

 private:
  std::vector<double> seconds_at_last_row_;
};

}  // namespace rouleau
