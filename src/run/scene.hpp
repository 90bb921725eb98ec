#pragma once
// The scene decides what runs: the list of stages a case needs, each with the reason it
// runs or is skipped (DESIGN.md, "skip what a scene doesn't need"). Host-only.
#include <string>
#include <vector>

#include "config/case_config.hpp"

namespace rouleau {

struct Stage {
  std::string name;    // "fluid", "cells", ...
  bool runs = true;
  std::string reason;  // why it runs in this form, or why it is skipped
};

std::vector<Stage> plan_stages(const CaseConfig& config, const DerivedQuantities& derived);
// The text printed by `rouleau run --explain`.
std::string describe_stages(const CaseConfig& config, const DerivedQuantities& derived,
                            const std::vector<Stage>& stages);

}  // namespace rouleau
