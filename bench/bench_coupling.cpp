// Time per coupled step and per stage (docs/design.md, "One time step"), for one and four red
// blood cells in a simple-shear box, at two fluid resolutions, against the same box
// without cells in the same run (the coupling's overhead).
//
//   BM_CoupledStep/cells/h_nm    one Simulation::advance(): forces, spread, fluid solve,
//                                interpolate, move (cells = 0: the fluid step alone)
//
// Box: 24 × 16 × 16 μm, periodic in x and z, walls at y = ±8 μm moving at ±400 μm/s
// (γ̇ = 50/s, as cases/rbc_shear), h = 1 μm (24 × 16 × 16 hexahedra) or 0.8 μm (30 × 20 × 20).
// Cells: the normal RBC (paper preset, 1039 nodes); four of them stacked face to face along
// y, 3.96 μm between centres, with the Morse interaction (the paper's four-cell stack,
// Figs. 7–11). dt = 2e-4 s (below the stable estimate at both resolutions).
// Counters: steps/s; per stage, milliseconds per step (ms_<stage>); cell nodes/s through
// the cell stages (everything but the fluid solve); the ratio of the step to the fluid step
// alone at the same resolution, measured in this run (overhead).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <Kokkos_Core.hpp>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "bench_common.hpp"
#include "config/load_case.hpp"
#include "geometry/cell_mesh.hpp"
#include "run/simulation.hpp"

namespace {

using rouleau::ImmersedCoupling;
using rouleau::Simulation;

std::string case_text(int cells, int elements_x) {
  const int ex = elements_x, ey = elements_x * 2 / 3, ez = ey;
  std::string text =
      "[case]\nname = \"bench_coupling\"\n[domain]\nlower_um = [-12, -8, -8]\nupper_um = [12, 8, 8]\n"
      "elements = [" + std::to_string(ex) + ", " + std::to_string(ey) + ", " + std::to_string(ez) + "]\n"
      "[boundary.x_min]\ntype = \"periodic\"\n[boundary.x_max]\ntype = \"periodic\"\n"
      "[boundary.z_min]\ntype = \"periodic\"\n[boundary.z_max]\ntype = \"periodic\"\n"
      "[boundary.y_min]\ntype = \"wall\"\nvelocity_um_s = [-400, 0, 0]\n"
      "[boundary.y_max]\ntype = \"wall\"\nvelocity_um_s = [400, 0, 0]\n"
      "[time]\ndt_s = 2e-4\nend_s = 1\n[output]\nfields = false\n";
  const double stack[4] = {-5.94, -1.98, 1.98, 5.94};
  for (int c = 0; c < cells; ++c)
    text += "[[cells]]\ncenter_um = [0, " + std::to_string(cells == 1 ? 0.0 : stack[c]) +
            ", 0]\norientation_deg = [90, 0, 0]\n";
  // The step is the one-cell estimate: the cost per step is measured over a few steps,
  // before the Morse law's own (smaller) stable step could matter.
  if (cells > 1) text += "[interaction]\nenabled = true\n[coupling]\nallow_unstable_step = true\n";
  return text;
}

std::unique_ptr<Simulation> make_simulation(int cells, int elements_x) {
  const auto folder = std::filesystem::temp_directory_path() / ("rouleau_bench_coupling_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const std::string path = (folder / "case.toml").string();
  std::ofstream(path) << case_text(cells, elements_x);
  return std::make_unique<Simulation>(rouleau::load_case(path), rouleau::default_mesh_cache_dir());
}

const char* const stages[] = {ImmersedCoupling::elastic_stage, ImmersedCoupling::interaction_stage,
                              ImmersedCoupling::inertia_stage,
                              ImmersedCoupling::spread_stage,  ImmersedCoupling::fluid_stage,
                              ImmersedCoupling::interpolate_stage, ImmersedCoupling::move_stage};

// Seconds per fluid-only step at each resolution, measured in this run.
std::map<int, double> fluid_step_seconds;

void BM_CoupledStep(benchmark::State& state) {
  const int cells = static_cast<int>(state.range(0));
  const int elements_x = static_cast<int>(24000 / state.range(1));
  std::unique_ptr<Simulation> simulation = make_simulation(cells, elements_x);
  std::map<std::string, double> before;
  double timed = 0.0;
  int steps = 0;
  // Warm-up: first touch, neighbour search, and the preconditioner, factored for the first
  // (backward Euler) step and again for BDF2's coefficients on the second.
  simulation->advance();
  simulation->advance();
  Kokkos::fence();
  for (const char* stage : stages) before[stage] = simulation->times().seconds(stage);
  for (auto _ : state) {
    Kokkos::Timer timer;
    simulation->advance();
    Kokkos::fence();
    const double seconds = timer.seconds();
    state.SetIterationTime(seconds);
    timed += seconds;
    ++steps;
  }
  const double per_step = timed / steps;
  state.counters["steps/s"] = 1.0 / per_step;
  double cell_stages = 0.0;
  for (const char* stage : stages) {
    const double ms = 1e3 * (simulation->times().seconds(stage) - before[stage]) / steps;
    std::string name = "ms_";
    for (const char* c = stage; *c; ++c) name += std::isalnum(static_cast<unsigned char>(*c)) ? *c : '_';
    state.counters[name] = ms;
    if (std::string(stage) != ImmersedCoupling::fluid_stage) cell_stages += 1e-3 * ms;
  }
  state.counters["gmres_iterations"] = simulation->last_report().fluid.gmres_iterations;
  if (cells == 0) {
    fluid_step_seconds[elements_x] = per_step;
  } else {
    const int nodes = simulation->cells().population->num_nodes();
    state.counters["cell_nodes"] = nodes;
    state.counters["cell nodes/s (cell stages)"] = cell_stages > 0 ? nodes / cell_stages : 0.0;
    if (fluid_step_seconds.count(elements_x)) state.counters["x fluid step"] = per_step / fluid_step_seconds[elements_x];
  }
}

}  // namespace

// h in nm (1000: 1 μm, 800: 0.8 μm); the fluid-only step runs first at each resolution.
BENCHMARK(BM_CoupledStep)
    ->ArgNames({"cells", "h_nm"})
    ->Args({0, 1000})
    ->Args({1, 1000})
    ->Args({4, 1000})
    ->Args({0, 800})
    ->Args({1, 800})
    ->Args({4, 800})
    ->Iterations(10)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  return rouleau::bench::run_benchmarks(argc, argv, [] {}, [] {});
}
