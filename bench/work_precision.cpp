// Work–precision of the fluid solver (bench/work_precision.md): the manufactured Navier–Stokes
// problem (fluid/manufactured_solution.hpp, Re = 1, steady, Newton) and its Stokes limit
// (Re = 0) solved on n³ boxes of hexahedra and of tetrahedra (each hexahedron cut in six),
// with ILU(0) and with the aggregation multigrid. Every point is a real solve from the
// zero state; its error is the relative L2 error of velocity and pressure against the
// exact solution, its work the wall time of the solver's construction (geometry, graph,
// preconditioner setup) plus the solve, on the Kokkos threads of this run.
//
//   work_precision [--out FILE.csv] [--sizes 4,6,8,12,16,24] [--quick]
//
// writes one CSV row per point; scripts/plot_work_precision.py turns it into the log–log
// figure and names the Pareto front.
#include <Kokkos_Core.hpp>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "fluid/fluid_errors.hpp"
#include "fluid/fluid_solver.hpp"
#include "fluid/manufactured_solution.hpp"
#include "mesh/fluid_mesh.hpp"

namespace {

using rouleau::FluidElementType;
using rouleau::PreconditionerType;

struct Point {
  const char* equations;
  const char* element;
  const char* preconditioner;
  int n = 0;
  int unknowns = 0;
  double velocity_error = 0.0, pressure_error = 0.0;
  int newton_iterations = 0, gmres_iterations = 0;
  bool converged = false;
  double seconds = 0.0;
};

Point solve(int n, double reynolds, FluidElementType element, PreconditionerType preconditioner) {
  Point point;
  point.equations = reynolds > 0 ? "navier_stokes" : "stokes";
  point.element = element == FluidElementType::tetrahedron4 ? "tetrahedra" : "hexahedra";
  point.preconditioner = preconditioner == PreconditionerType::multigrid ? "multigrid" : "ilu0";
  point.n = n;
  rouleau::FluidMesh mesh =
      rouleau::make_box_mesh({0, 0, 0}, {1, 1, 1}, {n, n, n}, {1, 1, 1}, {false, false, false});
  if (element == FluidElementType::tetrahedron4) mesh = rouleau::split_into_tetrahedra(mesh);
  point.unknowns = mesh.num_unknowns();
  // Unit scales (μ = 1, ρ = Re, L = U = 1); Newton to 1e-8 of the first residual, GMRES to
  // 1e-10 of its right-hand side: far below the discretization errors measured here.
  rouleau::FluidConfig fluid;
  fluid.viscosity = 1.0;
  fluid.density = reynolds;
  rouleau::FluidScales scales;
  scales.reynolds = reynolds;
  rouleau::SolverConfig settings;
  settings.newton_rtol = 1e-8;
  settings.newton_atol = 1e-12;
  settings.gmres_rtol = 1e-10;
  settings.gmres_restart = 100;
  settings.gmres_max_iterations = 20000;
  settings.preconditioner = preconditioner;
  const rouleau::ManufacturedSolution exact{reynolds};

  Kokkos::fence();
  Kokkos::Timer timer;
  rouleau::FluidSolver solver(mesh, fluid, std::array<rouleau::BoundaryConfig, 6>{}, settings, scales, reynolds == 0);
  rouleau::set_up_manufactured_problem(solver, mesh, exact);
  const rouleau::FluidSolveReport report = solver.solve_steady();
  Kokkos::fence();
  point.seconds = timer.seconds();

  point.converged = report.converged;
  point.newton_iterations = report.newton_iterations;
  point.gmres_iterations = report.gmres_iterations;
  const rouleau::FluidErrors e = rouleau::fluid_l2_errors(solver.fluid_operator(), solver.state(), exact);
  point.velocity_error = e.velocity / e.velocity_norm;
  point.pressure_error = e.pressure / e.pressure_norm;
  return point;
}

std::vector<int> parse_sizes(const std::string& list) {
  std::vector<int> sizes;
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) sizes.push_back(std::stoi(item));
  return sizes;
}

}  // namespace

int main(int argc, char* argv[]) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  std::string out = "work_precision.csv";
  std::vector<int> hexahedra_sizes{4, 6, 8, 12, 16, 24, 32}, tetrahedra_sizes{4, 6, 8, 12, 16, 24};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else if (arg == "--sizes" && i + 1 < argc) {
      hexahedra_sizes = tetrahedra_sizes = parse_sizes(argv[++i]);
    } else if (arg == "--quick") {
      hexahedra_sizes = tetrahedra_sizes = {4, 8};
    } else {
      std::cerr << "work_precision: unknown argument '" << arg << "' (--out FILE, --sizes 4,8,16, --quick)\n";
      return 2;
    }
  }
  std::ofstream csv(out + ".part");
  csv << "equations,element,preconditioner,n,unknowns,velocity_error,pressure_error,newton_iterations,"
         "gmres_iterations,converged,seconds,threads\n";
  const int threads = Kokkos::DefaultExecutionSpace().concurrency();
  for (double reynolds : {1.0, 0.0})
    for (FluidElementType element : {FluidElementType::hexahedron8, FluidElementType::tetrahedron4})
      for (PreconditionerType preconditioner : {PreconditionerType::ilu0, PreconditionerType::multigrid})
        for (int n : element == FluidElementType::hexahedron8 ? hexahedra_sizes : tetrahedra_sizes) {
          const Point p = solve(n, reynolds, element, preconditioner);
          csv << p.equations << ',' << p.element << ',' << p.preconditioner << ',' << p.n << ',' << p.unknowns << ','
              << p.velocity_error << ',' << p.pressure_error << ',' << p.newton_iterations << ','
              << p.gmres_iterations << ',' << (p.converged ? 1 : 0) << ',' << p.seconds << ',' << threads << '\n';
          std::printf("%-13s %-10s %-9s n = %2d: %7d unknowns, errors u %.3e p %.3e, %d Newton, %4d GMRES, %8.3f s%s\n",
                      p.equations, p.element, p.preconditioner, p.n, p.unknowns, p.velocity_error, p.pressure_error,
                      p.newton_iterations, p.gmres_iterations, p.seconds, p.converged ? "" : "  NOT CONVERGED");
          std::fflush(stdout);
        }
  csv.close();
  // Renamed only when complete: an interrupted study leaves no half-written CSV.
  if (std::rename((out + ".part").c_str(), out.c_str()) != 0) {
    std::cerr << "work_precision: cannot rename " << out << ".part to " << out << "\n";
    return 1;
  }
  std::printf("wrote %s (%d threads)\n", out.c_str(), threads);
  return 0;
}
