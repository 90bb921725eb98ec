// Two red cells aggregating in quiescent plasma (paper Fig. 6): runs
// cases/aggregation/case.toml (or the file given), prints the gap and contact-area history
// and the scene's check: with the interaction the gap closes to the order of r0 and stays
// there; without it (--set interaction.enabled=false) it stays open.
//   case_aggregation [CASE.toml] [--out DIR] [--set KEY=VALUE]... (the options of `rouleau run`)
#include <cstdio>

#include "analysis/paper_checks.hpp"
#include "analysis/scene_checks.hpp"
#include "io/diagnostics_reader.hpp"
#include "run/run_case.hpp"

int main(int argc, char** argv) {
  // Inputs and run
  const auto run = rouleau::run_case_driver(argc, argv, ROULEAU_CASE_DIR "/case.toml", "runs/aggregation");
  if (!run.ran) return run.status;
  // What is special to this case: the gap between the two cells.
  const auto rows = rouleau::read_diagnostics(run.options.output_dir + "/diagnostics.csv");
  std::printf("%10s %10s %14s %12s %12s\n", "time_s", "gap_um", "contact_um2", "volume0_um3", "volume1_um3");
  for (const auto& row : rows)
    std::printf("%10.6f %10.4f %14.3f %12.3f %12.3f\n", row.at("time_s"), row.at("gap_0_1_um"),
                row.at("contact_area_0_1_um2"), row.at("cell0_volume_um3"), row.at("cell1_volume_um3"));
  const double r0 = run.config.interaction.morse.zero_force_length;
  const rouleau::AggregationCheck check = rouleau::check_aggregation(rows, r0);
  using Check = rouleau::AggregationCheck;
  if (run.config.interaction.enabled) {
    std::printf("check (interaction on): final gap %.4f um %s %.2f r0 = %.4f um: %s; last quarter's range %.4f um "
                "%s %.2f r0: %s\n",
                check.final_gap, check.closed ? "<" : ">=", Check::closed_gap_r0, Check::closed_gap_r0 * r0,
                check.closed ? "closed" : "NOT CLOSED", check.settled_gap_range, check.settled ? "<" : ">=",
                Check::settled_range_r0, check.settled ? "settled" : "NOT SETTLED");
  } else {
    std::printf("check (interaction off): final gap %.4f um %s %.2f x initial %.4f um: %s\n", check.final_gap,
                check.open ? ">=" : "<", Check::open_fraction, check.initial_gap, check.open ? "open" : "CLOSED");
  }
  rouleau::write_paper_checks(run.options.output_dir, rouleau::paper_rows(check, r0, run.config.interaction.enabled));
  return 0;
}
