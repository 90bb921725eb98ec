// The paper's scenes, reduced for CI: each runs its case file through the real executable
// on a coarser mesh and over a shorter time, and asserts the scene's check
// (src/analysis/scene_checks.hpp) as its README states it. The full versions and their
// measured checks are in each case's README.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "analysis/scene_checks.hpp"
#include "io/diagnostics_reader.hpp"
#include "run_rouleau.hpp"

namespace {

const std::string cases_dir = std::string(ROULEAU_SOURCE_DIR) + "/cases";

std::string fresh_output_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("rouleau_scene_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir.string();
}

// Runs cases/NAME/case.toml with `overrides` (each a --set) and returns its diagnostics.
rouleau::DiagnosticsRows run_scene(const std::string& name, const std::string& tag, const std::string& overrides) {
  const std::string out = fresh_output_dir(name + tag);
  const Outcome o = run_rouleau("run " + cases_dir + "/" + name + "/case.toml --no-progress --out " + out + overrides);
  EXPECT_EQ(o.exit_code, 0) << o.err;
  return rouleau::read_diagnostics(out + "/diagnostics.csv");
}

TEST(Scenes, TwoCellsAggregateAndStayWithTheInteractionAndNotWithout) {
  // cases/aggregation (Fig. 6) on h_f = 1 μm and the coarse cell mesh, 1.5 ms: the gap
  // closes from 0.5 μm to below 1.5 r0 and settles (the last quarter's range below
  // 0.2 r0); the enclosed volumes are held by the volume constraint. Without the
  // interaction nothing drives the cells: the gap stays open.
  const std::string reduced = " --set domain.elements=[12,12,10] --set cell_kinds.normal.resolution=coarse"
                              " --set output.fields=false";
  const auto with = run_scene("aggregation", "_on", reduced + " --set time.end_s=0.0015");
  const double r0 = 0.25;
  const auto on = rouleau::check_aggregation(with, r0);
  std::printf("interaction on: gap %.4f -> %.4f um (closed below %.4f), last quarter's range %.2e um, contact area "
              "%.3f um^2\n", on.initial_gap, on.final_gap, rouleau::AggregationCheck::closed_gap_r0 * r0,
              on.settled_gap_range, on.final_contact_area);
  EXPECT_TRUE(on.closed);
  EXPECT_TRUE(on.settled);
  for (const char* volume : {"cell0_volume_um3", "cell1_volume_um3"}) {
    const auto v = rouleau::diagnostics_column(with, volume);
    EXPECT_NEAR(v.back(), v.front(), 0.01 * v.front()) << volume;
  }
  const auto without = run_scene("aggregation", "_off", reduced + " --set time.end_s=0.0003 --set interaction.enabled=false");
  const auto off = rouleau::check_aggregation(without, r0);
  std::printf("interaction off: gap %.4f -> %.4f um\n", off.initial_gap, off.final_gap);
  EXPECT_TRUE(off.open);
}

}  // namespace
