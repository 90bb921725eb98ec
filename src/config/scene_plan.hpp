#pragma once
// The scene decides what runs, in this one place: from the case it plans the stages a run
// needs, each with the reason it runs in its form or is skipped (a stage that cannot change
// the result is not built). `rouleau run --explain` prints the plan; the simulation builds
// its stages from the same plan (run/simulation.hpp, coupling/immersed_coupling.hpp).
// Host-only.
#include <string>
#include <vector>

#include "config/case_config.hpp"

namespace rouleau {

// The names of the coupled step's stages: as --explain lists them, as the step runs and
// times them (coupling/immersed_coupling.hpp, coupling/cell_forces.hpp) and as the run
// log's time per stage and the diagnostics' time columns name them.
namespace stage_name {
inline constexpr const char* elastic_forces = "neo-Hookean forces";
inline constexpr const char* interaction_forces = "Morse forces";
inline constexpr const char* wall_repulsion = "wall repulsion";
inline constexpr const char* inertia = "inertia/buoyancy";
inline constexpr const char* spread = "RKPM spread";
inline constexpr const char* cell_stiffness = "cell stiffness (semi-implicit)";
inline constexpr const char* fluid_solve = "fluid solve";
inline constexpr const char* interpolate = "RKPM interpolate";
inline constexpr const char* film_drainage = "film drainage (sub-grid)";
inline constexpr const char* move_cells = "move cells";
}  // namespace stage_name

struct Stage {
  std::string name;    // a stage_name, or what the plan describes besides: "fluid operator", "cells", ...
  bool runs = true;
  std::string reason;  // why it runs in this form, or why it is skipped
};

struct ScenePlan {
  // The stages in the order they run, for --explain.
  std::vector<Stage> stages;
  // The choices the stages are built from (each one a line of `stages`).
  bool stencil = false;         // the Stokes operator as the uniform-box stencil
  bool moves_cells = false;     // a time loop with cells: the coupled step
  bool morse_forces = false;    // the Morse interaction between cell surfaces
  bool wall_repulsion = false;  // a vessel wall's repulsion of cell surface nodes
  bool inertia = false;         // (ρ_s − ρ_f)(g − dv/dt) at the cell nodes
  bool semi_implicit = false;   // the cells' stiffness in the fluid solve
  bool film_drainage = false;   // the sub-grid film model between close cells
  // Without skips (scene.skip_unneeded_stages = false): the Morse list rebuilt every step,
  // the RKPM correction everywhere.
  bool rebuild_morse_list_every_step = false;
  bool rkpm_correction_everywhere = false;
};

ScenePlan plan_scene(const CaseConfig& config, const DerivedQuantities& derived);
// The text printed by `rouleau run --explain`.
std::string describe_scene(const CaseConfig& config, const DerivedQuantities& derived, const ScenePlan& plan);

}  // namespace rouleau
