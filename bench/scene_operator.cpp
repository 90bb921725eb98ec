// One application of a case's fluid operator, timed on the case's own mesh: the yardstick
// of the scene benchmark (bench/scene_steps.py), whose overhead ratio is the seconds of one
// GMRES iteration over the seconds of this application. The operator is the one GMRES
// applies once per iteration, without the preconditioner and the cells' stiffness: the
// Stokes operator (the uniform-box stencil where the case's plan uses it) in the Stokes
// limit, the Navier–Stokes Jacobian action at the current state otherwise. The case is
// built as `rouleau run` builds it and stepped once, so the operator's coefficients are
// those of a time step.
//
//   scene_operator CASE.toml [--repeats N] [--set KEY=VALUE ...]
//
// prints one line: "unknowns <n> seconds_per_application <s> path <stencil|elements>".
// The thread count is Kokkos' (--kokkos-num-threads or OMP_NUM_THREADS).
#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "config/load_case.hpp"
#include "geometry/mesh_cache.hpp"
#include "run/simulation.hpp"

namespace {
using rouleau::FluidOperator;
using Vector = Kokkos::View<double*>;

// result = A direction, as GMRES applies it (fluid_solver.cpp's operator, without the cells).
void apply(const FluidOperator& op, const bool stokes, const Vector& state, const Vector& state_gradient,
           const Vector& direction, const Vector& result) {
  if (stokes)
    op.linear_action(direction, result);
  else
    op.jacobian_action(state, state_gradient, direction, result);
}
}  // namespace

int main(int argc, char* argv[]) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  std::string case_file;
  std::vector<std::string> overrides;
  int repeats = 50;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--repeats" && i + 1 < argc)
      repeats = std::max(1, std::stoi(argv[++i]));
    else if (arg == "--set" && i + 1 < argc)
      overrides.push_back(argv[++i]);
    else if (case_file.empty() && arg.rfind("--", 0) != 0)
      case_file = arg;
    else {
      std::cerr << "scene_operator: unknown argument '" << arg << "' (CASE.toml [--repeats N] [--set KEY=VALUE])\n";
      return 2;
    }
  }
  if (case_file.empty()) {
    std::cerr << "scene_operator: no case file (scene_operator CASE.toml [--repeats N])\n";
    return 2;
  }
  try {
    const rouleau::CaseConfig config = rouleau::load_case(case_file, overrides);
    rouleau::Simulation simulation(config, rouleau::default_mesh_cache_dir());
    simulation.advance();
    const rouleau::FluidSolver& fluid = simulation.fluid();
    const FluidOperator& op = fluid.fluid_operator();
    const int n = op.num_unknowns();
    const bool stokes = fluid.stokes();
    Vector state("scene_operator::state", n), gradient, direction("scene_operator::direction", n),
        result("scene_operator::result", n);
    Kokkos::deep_copy(state, Kokkos::subview(fluid.state(), std::make_pair(0, n)));
    if (!stokes && op.coefficients().viscous_reconstruction) {
      gradient = Vector("scene_operator::gradient", 9 * op.mesh().num_dof_nodes);
      op.project_gradient(state, gradient);
    }
    Kokkos::deep_copy(direction, state);
    apply(op, stokes, state, gradient, direction, result);  // warm-up
    std::vector<double> seconds;
    for (int r = 0; r < repeats; ++r) {
      Kokkos::fence();
      Kokkos::Timer timer;
      apply(op, stokes, state, gradient, direction, result);
      Kokkos::fence();
      seconds.push_back(timer.seconds());
    }
    std::sort(seconds.begin(), seconds.end());
    std::printf("unknowns %d seconds_per_application %.6e path %s\n", n, seconds[seconds.size() / 2],
                stokes && op.uses_stencil() ? "stencil" : "elements");
  } catch (const std::exception& error) {
    std::cerr << "scene_operator: " << case_file << ": " << error.what() << "\n";
    return 2;
  }
  return 0;
}
