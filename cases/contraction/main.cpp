// Cells, or plasma alone, through a micro-vessel contraction (paper Figs. 13-15): runs
// cases/contraction/case.toml (or the file given; `--set 'cells=[]'` for plasma) and sets the
// driving pressure against Hagen–Poiseuille's drop summed over the cross-sections,
// (8 μ Q / π) ∫ dx / R(x)⁴, and the outflow against the inflow; with cells, it prints how
// many have passed the throat over time with the driving pressure, and the paper's
// statement: normal cells pass the throat, sickle cells do not (check_contraction_passage).
//   case_contraction [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/paper_checks.hpp"
#include "analysis/scene_checks.hpp"
#include "geometry/vessel_profile.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/contraction");
  if (!run.ran) return run.status;
  // What is special to this case: the cells' passage, the pressure the contraction costs,
  // and mass balance.
  const auto rows = rouleau::read_diagnostics(run.options.output_dir + "/diagnostics.csv");
  const rouleau::VesselProfile& profile = run.config.vessel.profile;
  const int cells = static_cast<int>(run.config.cells.size());
  if (cells > 0) {
    const double throat_exit = profile.inlet_length + profile.contraction_length + profile.throat_length;
    std::printf("%10s %12s %12s   (cells past the throat's exit at x = %.1f um, of %d)\n", "time_s", "cells_past",
                "driving_Pa", throat_exit, cells);
    for (const auto& row : rows)
      std::printf("%10.4f %12d %12.5f\n", row.at("time_s"), rouleau::cells_past(row, cells, throat_exit),
                  row.at("driving_pressure_Pa"));
    // The paper's statement (Figs. 13-15): normal cells pass, sickle cells block the entrance.
    std::vector<std::string> kinds;
    for (const auto& cell : run.config.cells) kinds.push_back(cell.kind);
    const double throat_entry = profile.inlet_length + profile.contraction_length;
    const auto passage = rouleau::check_contraction_passage(rows, kinds, throat_entry, throat_exit);
    for (int c = 0; c < cells; ++c)
      std::printf("cell %d (%s): centroid at x = %.2f um at t = %.3f s; %s\n", c, kinds[c].c_str(),
                  passage.final_position[c], passage.end_time,
                  passage.passed[c] ? ("past the throat's exit since t = " +
                                       std::to_string(passage.passage_time[c]) + " s").c_str()
                  : passage.blocked[c] ? "stalled at the throat's entrance or behind a cell held there (blocked)"
                                       : "not past the throat's exit, not stalled at its entrance");
    // A statement about a kind the run does not hold does not apply.
    const auto verdict = [](int cells_of_kind, bool holds) {
      return cells_of_kind == 0 ? "does not apply (none in the run)" : holds ? "met" : "NOT MET";
    };
    std::printf("check (normal cells pass the throat): %s; (sickle cells stall at its entrance, in the same time, "
                "and hold the flow back: driving pressure %.2f times Hagen-Poiseuille's at the end, >= %.0f): %s; the "
                "paper's statement: %s\n",
                verdict(passage.normal_cells, passage.normal_cells_passed), passage.final_pressure_ratio,
                rouleau::ContractionPassageCheck::blocked_pressure_ratio,
                verdict(passage.sickle_cells, passage.sickle_cells_blocked), passage.met() ? "met" : "NOT MET");
    std::printf("most compressed cell element: J = %.3f at t = %.3f s (%s, J > %.1f)\n",
                passage.smallest_volume_ratio, passage.smallest_volume_ratio_time,
                passage.no_element_crushed ? "none crushed" : "CRUSHED",
                rouleau::ContractionPassageCheck::crushed_volume_ratio);
    // Fig. 14 after the throat: slower in the diffuser, closer together at the outlet.
    const double diffuser_exit = throat_exit + profile.diffuser_length;
    const auto outlet = rouleau::check_contraction_outlet(rows, kinds, throat_entry, throat_exit, diffuser_exit);
    for (std::size_t i = 0; i < outlet.cells.size(); ++i)
      std::printf("cell %d: %.3f um/s across the throat, %.3f um/s across the diffuser\n", outlet.cells[i],
                  outlet.throat_speed[i], outlet.diffuser_speed[i]);
    if (outlet.time_all_passed >= 0.0)
      std::printf("normal cells' neighbour spacing %.3f um at the start, %.3f um at t = %.3f s when the last passed "
                  "the throat (ratio %.3f)\n",
                  outlet.initial_spacing, outlet.spacing_after, outlet.time_all_passed, outlet.spacing_ratio);
    auto paper = rouleau::paper_rows(passage, kinds, throat_exit);
    const auto after = rouleau::paper_rows(outlet);
    paper.insert(paper.end(), after.begin(), after.end());
    rouleau::write_paper_checks(run.options.output_dir, paper);
  }
  const auto& last = rows.back();
  const double inflow = last.at("flow_rate_inlet_um3_s"), outflow = last.at("flow_rate_outlet_um3_s");
  const double drop = last.at("driving_pressure_Pa");
  const double lubrication = rouleau::vessel_poiseuille_drop(profile, run.config.fluid.viscosity, outflow);
  std::printf("flow rate in %.4f, out %.4f um^3/s (relative difference %.1e)\n", inflow, outflow,
              std::fabs(outflow - inflow) / inflow);
  std::printf("driving pressure %.5f Pa; Hagen-Poiseuille summed over the cross-sections %.5f Pa; ratio %.4f "
              "(the entrance and exit losses)\n",
              drop, lubrication, drop / lubrication);
  return 0;
}
