#pragma once
// The reduced two-cell aggregation that the restart and MPI tests run through the real
// executable (semi-implicit, Morse on at ten times the case's depth, 25 μJ/m², coarse cells on a
// 12x12x10 box), 8.5e-5 s steps, one diagnostics row per step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/checkpoint_file.hpp"

namespace {

const std::string cases_dir = std::string(ROULEAU_SOURCE_DIR) + "/cases";

constexpr double aggregation_step_s = 8.5e-5;
std::string end_after(int steps) {
  char text[64];
  std::snprintf(text, sizeof text, " --set time.end_s=%.17g", steps * aggregation_step_s);
  return text;
}
std::vector<std::string> reduced_aggregation_arguments(const std::string& out, int threads, int steps) {
  std::vector<std::string> arguments{"run", cases_dir + "/aggregation/case.toml", "--out", out, "--threads",
                                     std::to_string(threads), "--no-progress"};
  for (const char* setting : {"domain.elements=[12,12,10]", "cell_kinds.normal.resolution=coarse",
                              "coupling.scheme=semi_implicit", "time.dt_s=8.5e-5", "output.diagnostics_every_steps=1",
                              "interaction.strength_multiplier=50"}) {
    arguments.push_back("--set");
    arguments.push_back(setting);
  }
  arguments.push_back("--set");
  arguments.push_back(end_after(steps).substr(7));
  return arguments;
}
std::string reduced_aggregation(const std::string& out, int threads, int steps) {
  std::string command;
  for (const std::string& argument : reduced_aggregation_arguments(out, threads, steps)) command += argument + " ";
  return command;
}

// Wall times (per stage and in all) differ between any two runs; every other number must not.
bool is_wall_time(const std::string& name) {
  return name == "run/stage_seconds" || name == "wall_time_s" || (name.find("time_") == 0 && name != "time_s");
}

// The checkpoints of step `step` of two runs hold the same state within `bound`: for every
// entry but wall times, max |a − b| / max |a| < bound (printed). Returns whether any entry
// differs at all.
bool expect_states_agree(const std::string& run_a, const std::string& run_b, int step, double bound) {
  const auto a = rouleau::read_checkpoint_file(rouleau::CheckpointStore(run_a, 1).path_of(step));
  const auto b = rouleau::read_checkpoint_file(rouleau::CheckpointStore(run_b, 1).path_of(step));
  EXPECT_EQ(a.time, b.time);
  bool any_difference = false;
  for (const auto& [name, values] : a.reals) {
    if (is_wall_time(name)) continue;
    if (!b.reals.count(name)) {
      ADD_FAILURE() << name << " is missing from " << run_b;
      continue;
    }
    const std::vector<double>& other = b.reals.at(name);
    if (values.size() != other.size()) {
      ADD_FAILURE() << name << ": " << values.size() << " entries against " << other.size();
      continue;
    }
    double largest = 0.0, difference = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      largest = std::max(largest, std::fabs(values[i]));
      difference = std::max(difference, std::fabs(values[i] - other[i]));
    }
    const double relative = largest > 0.0 ? difference / largest : difference;
    std::printf("%-32s largest relative difference %.3e\n", name.c_str(), relative);
    EXPECT_LT(relative, bound) << name;
    any_difference = any_difference || difference > 0.0;
  }
  return any_difference;
}

}  // namespace
