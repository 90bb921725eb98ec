// Throughput of the matrix-free stabilized Navier–Stokes operator, set against the
// machine's achievable memory bandwidth, and GMRES iterations per Stokes solve as the
// mesh is refined (with and without block Jacobi).
//
//   BM_JacobianAction/n   J(U)δ, Navier–Stokes (convection 1, Re 1, transient BDF1
//                         coefficients, history and body force set), dual numbers
//   BM_LinearAction/n/path  Aδ, the Stokes limit (convection 0); path 0: element by element,
//                         path 1: the uniform-box stencil from one reference element
//                         (fluid/uniform_box_stencil.hpp), what FluidSolver runs on such a box
//   BM_Residual/n         R(U) with τ frozen at U, same setting as BM_JacobianAction
//   BM_Triad/n            a = b + s·c over as many bytes as BM_JacobianAction/n moves
//   BM_StokesSolve/n/pc   one steady Stokes solve of a manufactured problem (pc 0: none, 1: block
//                         Jacobi, 2: ILU(0), 3: aggregation multigrid), one iteration, GMRES iterations reported
//   BM_VesselJacobianAction/n, BM_VesselLinearAction/n
//                         the same passes on a Gmsh tube (R = 5 μm, L = 40 μm) of 4-node
//                         tetrahedra with about as many nodes as the box's (n + 1)³
//
// Mesh: the unit cube in n³ trilinear hexahedra, no periodicity, walls (Dirichlet
// velocity) on all six sides; or the tube, no-slip on its wall, inlet and outlet. The
// state and direction are random in [−1, 1].
//
// Byte model ("GB/s"): the bytes a perfect implementation must move per application —
// each nodal vector it reads gathered exactly once (4 doubles per node), the result
// written once (4 doubles per node), and per element the stored quadrature geometry
// (8 points × 10 doubles: J⁻¹ and det J·w; 4 points on a tetrahedron), the element size
// h (1 double) and the connectivity (8 ints; 4). The nodal vectors read are
//   jacobian_action: state, direction, BDF history, body force     (4 vectors)
//   residual:        state (= frozen, the same View), history, force (3 vectors)
//   linear_action:   direction                                       (1 vector)
// The stencil path needs no element data: its model is the direction read and the result
// written once (8 doubles per node); its two-pass form also writes and reads the projected
// gradient (18 doubles per node), which the model does not count.
// Dirichlet rows (O(n²) entries) and the ScatterView's per-thread copies are not
// counted: the latter are an implementation cost, which is what the ratio exposes.
// The triad counts 3 arrays × 8 bytes per entry (STREAM convention, no write-allocate).
#include <benchmark/benchmark.h>

#include <Kokkos_Core.hpp>
#include <Kokkos_Random.hpp>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_operator.hpp"
#include "fluid/fluid_element_types.hpp"
#include "fluid/fluid_solver.hpp"
#include "fluid/manufactured_solution.hpp"
#include "geometry/mesh_cache.hpp"
#include "mesh/fluid_mesh.hpp"

namespace {

using rouleau::FluidCoefficients;
using rouleau::FluidMesh;
using rouleau::FluidOperator;
using rouleau::Vector;

using rouleau::bench::bytes_per_double;
using rouleau::bench::bytes_per_int;
using rouleau::bench::time_applications;
constexpr double geometry_doubles_per_element = 8.0 * rouleau::geometry_entries;  // hexahedra

enum class Pass { jacobian_action, linear_action, residual, stencil_linear_action };

int vectors_read(Pass pass) {
  switch (pass) {
    case Pass::jacobian_action: return 4;
    case Pass::residual: return 3;
    case Pass::linear_action:
    case Pass::stencil_linear_action: return 1;
  }
  return 0;
}

// The byte model above, for one application on `mesh`.
double operator_bytes(const FluidMesh& mesh, Pass pass) {
  const double unknowns = mesh.num_unknowns();
  const double geometry_doubles = rouleau::fluid_quadrature_points(mesh.element_type) * rouleau::geometry_entries;
  const double per_element = (geometry_doubles + 1.0) * bytes_per_double + mesh.nodes_per_element * bytes_per_int;
  const double elements = pass == Pass::stencil_linear_action ? 0.0 : mesh.num_elements;
  return (vectors_read(pass) + 1) * unknowns * bytes_per_double + elements * per_element;
}

// Flops of one stencil application (viscous reconstruction on): per node and present
// neighbour offset, 9 multiply-adds for G (kernels/fluid_stencil.hpp), 16 for the 4×4
// block and 9 for the pressure row's G term: 68 flops. A direction of p dof planes has
// 3p offsets present over its nodes if periodic, 3p − 2 if walled.
double stencil_flops(const FluidMesh& mesh) {
  double pairs = 1.0;
  for (int d = 0; d < 3; ++d) {
    const int planes = mesh.structured_elements[d] + (mesh.periodic[d] ? 0 : 1);
    pairs *= 3.0 * planes - (mesh.periodic[d] ? 0.0 : 2.0);
  }
  return 68.0 * pairs;
}

enum class Domain { box, tube };

// A Gmsh tube of radius 5 μm and length 40 μm whose element size gives about (n + 1)³
// nodes: Gmsh makes about 0.89 V/h³ nodes in it (measured at h = 0.52 μm).
FluidMesh tube_mesh(int n) {
  rouleau::VesselProfile tube;
  tube.radius = tube.throat_radius = 5.0;
  tube.inlet_length = 40.0;
  const double nodes = std::pow(n + 1.0, 3), volume = rouleau::vessel_volume(tube);
  const double h = std::cbrt(0.89 * volume / nodes);
  return rouleau::make_vessel_fluid_mesh(
      rouleau::vessel_mesh(tube, rouleau::VesselMeshSizes{h, 0.0}, rouleau::default_mesh_cache_dir()), tube);
}

// An operator on the unit cube (or the tube) with walls everywhere and random state,
// direction and sources. Built once per mesh and kept while benchmarks of that mesh run
// (Google Benchmark calls a benchmark function several times to size its loop).
struct OperatorProblem {
  int n;
  Domain domain;
  FluidMesh mesh;
  FluidOperator op;
  Vector state, direction, history, force, result;

  OperatorProblem(int cells, Domain shape)
      : n(cells),
        domain(shape),
        mesh(shape == Domain::box ? rouleau::make_box_mesh({0, 0, 0}, {1, 1, 1}, {cells, cells, cells}, {1, 1, 1},
                                                           {false, false, false})
                                  : tube_mesh(cells)),
        op(mesh, 1.0),
        state("state", mesh.num_unknowns()),
        direction("direction", mesh.num_unknowns()),
        history("history", mesh.num_unknowns()),
        force("force", mesh.num_unknowns()),
        result("result", mesh.num_unknowns()) {
    const auto bc = domain == Domain::box
                        ? rouleau::build_boundary_conditions(mesh, std::array<rouleau::BoundaryConfig, 6>{},
                                                             rouleau::FluidScales{})
                        : rouleau::build_boundary_conditions(
                              mesh, {{"inlet", {}}, {"outlet", {}}, {"wall", {}}}, rouleau::FluidScales{});
    op.set_dirichlet(bc.dirichlet_dofs, bc.dirichlet_values);
    Kokkos::Random_XorShift64_Pool<> pool(20240607);
    Kokkos::fill_random(state, pool, -1.0, 1.0);
    Kokkos::fill_random(direction, pool, -1.0, 1.0);
    Kokkos::fill_random(history, pool, -1.0, 1.0);
    Kokkos::fill_random(force, pool, -1.0, 1.0);
    Kokkos::fence();
  }

  // Navier–Stokes, Re = 1, one backward-Euler step of Δt = 0.1 (scaled), with the
  // projected viscous term in the strong residual, as FluidSolver runs it.
  void navier_stokes() {
    FluidCoefficients c;
    c.viscous_reconstruction = 1;
    c.reynolds = 1.0;
    c.mass_coefficient = 1.0 / 0.1;
    c.inverse_dt = 1.0 / 0.1;
    c.convection = 1;
    op.set_coefficients(c);
    op.set_sources(history, force);
  }
  // The steady Stokes limit (linear_action ignores the sources), with the projected
  // viscous term, as FluidSolver runs it.
  void stokes() {
    FluidCoefficients c;
    c.viscous_reconstruction = 1;
    c.reynolds = 0.0;
    c.convection = 0;
    op.set_coefficients(c);
    op.set_sources(rouleau::ConstVector(), rouleau::ConstVector());
  }
};

std::unique_ptr<OperatorProblem> cached_problem;

OperatorProblem& problem(int n, Domain domain = Domain::box) {
  if (!cached_problem || cached_problem->n != n || cached_problem->domain != domain) {
    cached_problem.reset();  // free the previous mesh first
    cached_problem = std::make_unique<OperatorProblem>(n, domain);
  }
  return *cached_problem;
}

void set_operator_counters(benchmark::State& state, const FluidMesh& mesh, Pass pass) {
  const double applications = static_cast<double>(state.iterations());
  state.counters["MDoF/s"] = benchmark::Counter(applications * mesh.num_unknowns() * 1e-6, benchmark::Counter::kIsRate);
  state.counters["elements/s"] = benchmark::Counter(applications * mesh.num_elements, benchmark::Counter::kIsRate);
  state.counters["GB/s"] = benchmark::Counter(applications * operator_bytes(mesh, pass) * 1e-9,
                                              benchmark::Counter::kIsRate);
  state.counters["unknowns"] = mesh.num_unknowns();
  state.counters["MB/application"] = operator_bytes(mesh, pass) * 1e-6;
}

// J(U)δ as GMRES applies it: the state's projected gradient computed once per Krylov solve.
void jacobian_action(benchmark::State& state, Domain domain) {
  OperatorProblem& p = problem(static_cast<int>(state.range(0)), domain);
  p.navier_stokes();
  rouleau::Vector state_gradient("state_gradient", 9 * p.mesh.num_dof_nodes);
  p.op.project_gradient(p.state, state_gradient);
  time_applications(state, [&] { p.op.jacobian_action(p.state, state_gradient, p.direction, p.result); });
  set_operator_counters(state, p.mesh, Pass::jacobian_action);
}

// Aδ; on the box, range(1) picks the path (0: element by element, 1: the stencil).
void linear_action(benchmark::State& state, Domain domain) {
  OperatorProblem& p = problem(static_cast<int>(state.range(0)), domain);
  p.stokes();
  const bool stencil = domain == Domain::box && state.range(1) == 1;
  p.op.allow_stencil(stencil);
  if (stencil && !p.op.uses_stencil()) {
    state.SkipWithError(("no stencil path: " + p.op.stencil_unavailable_reason()).c_str());
    return;
  }
  time_applications(state, [&] { p.op.linear_action(p.direction, p.result); });
  p.op.allow_stencil(true);
  set_operator_counters(state, p.mesh, stencil ? Pass::stencil_linear_action : Pass::linear_action);
  if (stencil)
    state.counters["GFLOP/s"] = benchmark::Counter(static_cast<double>(state.iterations()) * stencil_flops(p.mesh) * 1e-9,
                                                   benchmark::Counter::kIsRate);
  state.SetLabel(stencil ? "stencil" : "element by element");
}

void BM_JacobianAction(benchmark::State& state) { jacobian_action(state, Domain::box); }
void BM_LinearAction(benchmark::State& state) { linear_action(state, Domain::box); }
// The same two passes on the tetrahedral tube with about the box's number of unknowns.
void BM_VesselJacobianAction(benchmark::State& state) { jacobian_action(state, Domain::tube); }
void BM_VesselLinearAction(benchmark::State& state) { linear_action(state, Domain::tube); }

void BM_Residual(benchmark::State& state) {
  OperatorProblem& p = problem(static_cast<int>(state.range(0)));
  p.navier_stokes();
  time_applications(state, [&] { p.op.residual(p.state, p.state, p.result); });
  set_operator_counters(state, p.mesh, Pass::residual);
}

// The achievable floating-point rate of this build, the compute roof of the stencil path.
void BM_PeakFlops(benchmark::State& state) { rouleau::bench::peak_flops(state); }

// STREAM triad over the bytes BM_JacobianAction/n moves.
void BM_Triad(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int nodes = (n + 1) * (n + 1) * (n + 1), elements = n * n * n;
  rouleau::bench::triad(state, (vectors_read(Pass::jacobian_action) + 1) * 4.0 * nodes * bytes_per_double +
                                   elements * ((geometry_doubles_per_element + 1.0) * bytes_per_double +
                                               8 * bytes_per_int));
}

void BM_StokesSolve(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  // range(1): 0 no preconditioner, 1 block Jacobi, 2 ILU(0), 3 aggregation multigrid
  const rouleau::PreconditionerType preconditioner[4] = {
      rouleau::PreconditionerType::none, rouleau::PreconditionerType::block_jacobi, rouleau::PreconditionerType::ilu0,
      rouleau::PreconditionerType::multigrid};
  const char* preconditioner_name[4] = {"no preconditioner", "block Jacobi", "ILU(0)", "aggregation multigrid"};
  const int choice = static_cast<int>(state.range(1));
  const FluidMesh mesh = rouleau::make_box_mesh({0, 0, 0}, {1, 1, 1}, {n, n, n}, {1, 1, 1}, {false, false, false});
  rouleau::FluidConfig fluid;
  fluid.viscosity = 1.0;
  fluid.density = 0.0;
  rouleau::FluidScales scales;  // unit scales: dimensional = scaled
  scales.reynolds = 0.0;
  rouleau::SolverConfig settings;
  settings.gmres_rtol = 1e-8;
  settings.gmres_restart = 100;
  // Unpreconditioned GMRES(100) stagnates near 2e-8 at 16³ (20000 iterations, 190 s, did
  // not reach 1e-8): cap it, and report the residual reduction reached.
  settings.gmres_max_iterations = 4000;
  settings.preconditioner = preconditioner[choice];

  rouleau::FluidSolveReport report;
  for (auto _ : state) {
    // Setup (operator geometry, Dirichlet values, body force) outside the timed region;
    // the preconditioner is built inside solve_steady() and so is timed (for ILU(0) the
    // graph and symbolic factorization are built with the solver, outside).
    rouleau::FluidSolver solver(mesh, fluid, std::array<rouleau::BoundaryConfig, 6>{}, settings, scales, true);
    // The manufactured Stokes problem (fluid/manufactured_solution.hpp, Re = 0).
    rouleau::set_up_manufactured_problem(solver, mesh, rouleau::ManufacturedSolution{0.0});
    Kokkos::fence();
    Kokkos::Timer timer;
    report = solver.solve_steady();
    Kokkos::fence();
    state.SetIterationTime(timer.seconds());
  }
  state.counters["converged"] = report.converged ? 1 : 0;
  // ‖R‖ after the solve over ‖R(U₀)‖ (the Krylov solve's reduction of the true residual).
  state.counters["residual_reduction"] =
      std::hypot(report.momentum_residual, report.continuity_residual) / report.initial_residual;
  const double iterations = report.gmres_iterations;
  state.counters["gmres_iterations"] = iterations;
  state.counters["unknowns"] = mesh.num_unknowns();
  state.counters["MDoF/s"] = benchmark::Counter(static_cast<double>(state.iterations()) * iterations *
                                                    mesh.num_unknowns() * 1e-6,
                                                benchmark::Counter::kIsRate);
  state.SetLabel(std::string(preconditioner_name[choice]) +
                 (report.converged ? "" : ", NOT CONVERGED: " + report.failure));
}

}  // namespace

// The operator benchmarks' mesh sizes, n³ elements.
void operator_sizes(benchmark::internal::Benchmark* b) {
  b->ArgName("n")->Arg(16)->Arg(32)->Arg(48)->Arg(64)->UseManualTime()->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_PeakFlops)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Triad)->Apply(operator_sizes);
BENCHMARK(BM_JacobianAction)->Apply(operator_sizes);
BENCHMARK(BM_LinearAction)
    ->ArgNames({"n", "path"})
    ->ArgsProduct({{16, 32, 48, 64}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Residual)->Apply(operator_sizes);
// Tubes of about 17³, 33³, 49³ nodes, as the boxes of n = 16, 32, 48.
void vessel_sizes(benchmark::internal::Benchmark* b) {
  b->ArgName("n")->Arg(16)->Arg(32)->Arg(48)->UseManualTime()->Unit(benchmark::kMillisecond);
}
BENCHMARK(BM_VesselJacobianAction)->Apply(vessel_sizes);
BENCHMARK(BM_VesselLinearAction)->Apply(vessel_sizes);
BENCHMARK(BM_StokesSolve)
    ->ArgNames({"n", "preconditioner"})
    ->Args({8, 3})
    ->Args({16, 3})
    ->Args({24, 3})
    ->Args({32, 3})
    ->Args({48, 3})
    ->Args({64, 3})
    ->Args({8, 2})
    ->Args({16, 2})
    ->Args({24, 2})
    ->Args({32, 2})
    ->Args({48, 2})
    ->Args({8, 1})
    ->Args({16, 1})
    ->Args({24, 1})
    ->Args({32, 1})
    ->Args({8, 0})
    ->Args({16, 0})
    ->Iterations(1)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  return rouleau::bench::run_benchmarks(argc, argv, [] {}, [] { cached_problem.reset(); });
}
