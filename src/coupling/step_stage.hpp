#pragma once
// One stage of a time step: its name (as timed, printed and profiled) and what it does.
// A step is a list of them, built once from the scene's plan (config/scene_plan.hpp) and
// run in order; each stage reads and writes the step's state, and the comment where it is
// built names what it reads and writes.
#include <functional>
#include <string>
#include <vector>

#include "util/profiling_region.hpp"
#include "util/stage_times.hpp"

namespace rouleau {

struct StepStage {
  std::string name;
  // Runs the stage; false ends the step there (a fluid solve that did not converge).
  std::function<bool()> run;
};

// Runs `stages` in order, each timed under its name; false when one ended the step.
inline bool run_stages(const std::vector<StepStage>& stages, StageTimes& times) {
  for (const StepStage& stage : stages) {
    const ProfilingRegion region("rouleau::" + stage.name);
    if (!times.time(stage.name, stage.run)) return false;
  }
  return true;
}

}  // namespace rouleau
