// Physics validation of the fluid solver against exact solutions: Couette flow, plane
// Poiseuille flow, and manufactured solutions of the Stokes and Navier–Stokes equations.
// Each test prints the errors and convergence rates it measured.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fluid/fluid_errors.hpp"
#include "fluid/fluid_solver.hpp"
#include "fluid/manufactured_solution.hpp"
#include "unit_fluid.hpp"

namespace rouleau {
namespace {

using testing::tight_solver;
using testing::unit_fluid;
using testing::unit_scales;

// Observed order between meshes of n_coarse and n_fine elements per direction.
double rate(double coarse_error, double fine_error, int n_coarse, int n_fine) {
  return std::log(coarse_error / fine_error) / std::log(double(n_fine) / n_coarse);
}

// u = (y, 0, 0) between a wall at rest (y = 0) and one moving at U = 1 (y = 1).
struct CouetteExact {
  KOKKOS_INLINE_FUNCTION void operator()(const double x[3], double u[3], double& p) const {
    u[0] = x[1];
    u[1] = u[2] = 0.0;
    p = 0.0;
  }
};

TEST(FluidFlows, CouetteFlowIsLinearToSolverTolerance) {
  // Navier–Stokes (Re = 10, convection on): the linear profile is exact for trilinear elements.
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {2, 1, 1}, {4, 6, 2}, {1, 1.5, 1}, {true, false, true});
  std::array<BoundaryConfig, 6> sides{};
  sides[Side::x_min].type = sides[Side::x_max].type = BoundaryType::periodic;
  sides[Side::z_min].type = sides[Side::z_max].type = BoundaryType::periodic;
  sides[Side::y_max].velocity = {1.0, 0.0, 0.0};
  FluidSolver solver(mesh, unit_fluid(10.0), sides, tight_solver(), unit_scales(10.0), false);
  const FluidSolveReport report = solver.solve_steady();
  ASSERT_TRUE(report.converged) << report.failure;
  const FluidErrors e = fluid_l2_errors(solver.fluid_operator(), solver.state(), CouetteExact{});
  std::printf("Couette (graded, Re = 10): L2 velocity error %.2e (relative %.2e), %d Newton, %d GMRES\n", e.velocity,
              e.velocity / e.velocity_norm, report.newton_iterations, report.gmres_iterations);
  EXPECT_LT(e.velocity / e.velocity_norm, 1e-8);
  EXPECT_LT(e.pressure, 1e-8);
}

// Plane Poiseuille flow driven by a body force f_x = 8 μ U / H²: u = 4 U y (1 − y).
struct PoiseuilleExact {
  KOKKOS_INLINE_FUNCTION void operator()(const double x[3], double u[3], double& p) const {
    u[0] = 4.0 * x[1] * (1.0 - x[1]);
    u[1] = u[2] = 0.0;
    p = 0.0;
  }
};

TEST(FluidFlows, PoiseuilleFlowConvergesAtSecondOrder) {
  std::array<BoundaryConfig, 6> sides{};
  sides[Side::x_min].type = sides[Side::x_max].type = BoundaryType::periodic;
  sides[Side::z_min].type = sides[Side::z_max].type = BoundaryType::periodic;
  std::vector<double> errors;
  const std::vector<int> sizes{4, 8, 16, 32};
  for (int n : sizes) {
    const FluidMesh mesh = make_box_mesh({0, 0, 0}, {1, 1, 0.5}, {2, n, 1}, {1, 1, 1}, {true, false, true});
    FluidConfig fluid = unit_fluid(0.0);
    fluid.body_force = {8.0, 0.0, 0.0};
    FluidSolver solver(mesh, fluid, sides, tight_solver(), unit_scales(0.0), true);
    const FluidSolveReport report = solver.solve_steady();
    ASSERT_TRUE(report.converged) << report.failure;
    const FluidErrors e = fluid_l2_errors(solver.fluid_operator(), solver.state(), PoiseuilleExact{});
    errors.push_back(e.velocity / e.velocity_norm);
    std::printf("Poiseuille ny = %2d: relative L2 velocity error %.3e%s", n, errors.back(),
                errors.size() > 1 ? "" : "\n");
    const size_t k = errors.size() - 1;
    if (k > 0) std::printf(", rate %.2f\n", rate(errors[k - 1], errors[k], sizes[k - 1], sizes[k]));
  }
  EXPECT_NEAR(rate(errors[2], errors[3], sizes[2], sizes[3]), 2.0, 0.15);
  EXPECT_LT(errors.back(), 1e-3);
}

// The manufactured solution: fluid/manufactured_solution.hpp.

// Solves the manufactured problem on n³ elements; returns relative velocity and pressure errors.
// On hexahedra, or on tetrahedra (the same nodes, each hexahedron cut in six).
std::pair<double, double> manufactured_errors(int n, double reynolds, bool stokes, int& gmres_iterations,
                                              PreconditionerType preconditioner = PreconditionerType::ilu0,
                                              FluidElementType element = FluidElementType::hexahedron8,
                                              MultigridPrecision precision = MultigridPrecision::single_precision) {
  FluidMesh mesh = make_box_mesh({0, 0, 0}, {1, 1, 1}, {n, n, n}, {1, 1, 1}, {false, false, false});
  if (element == FluidElementType::tetrahedron4) mesh = split_into_tetrahedra(mesh);
  const ManufacturedSolution exact{reynolds};
  // Newton to 1e-8 of the initial residual: five orders below the discretization error.
  SolverConfig settings = tight_solver();
  settings.newton_rtol = 1e-8;
  settings.preconditioner = preconditioner;
  settings.multigrid_precision = precision;
  FluidSolver solver(mesh, unit_fluid(reynolds), std::array<BoundaryConfig, 6>{}, settings, unit_scales(reynolds),
                     stokes);
  set_up_manufactured_problem(solver, mesh, exact);
  const FluidSolveReport report = solver.solve_steady();
  EXPECT_TRUE(report.converged) << report.failure;
  gmres_iterations = report.gmres_iterations;
  const FluidErrors e = fluid_l2_errors(solver.fluid_operator(), solver.state(), exact);
  return {e.velocity / e.velocity_norm, e.pressure / e.pressure_norm};
}

void check_manufactured_convergence(const char* name, double reynolds, bool stokes,
                                    FluidElementType element = FluidElementType::hexahedron8) {
  std::vector<std::pair<double, double>> errors;
  const std::vector<int> sizes{8, 16, 24};
  for (int n : sizes) {
    int iterations = 0;
    errors.push_back(manufactured_errors(n, reynolds, stokes, iterations, PreconditionerType::ilu0, element));
    std::printf("%s n = %2d: relative L2 error velocity %.3e, pressure %.3e (%d GMRES iterations)", name, n,
                errors.back().first, errors.back().second, iterations);
    const size_t k = errors.size() - 1;
    if (k > 0)
      std::printf(", rates %.2f, %.2f", rate(errors[k - 1].first, errors[k].first, sizes[k - 1], sizes[k]),
                  rate(errors[k - 1].second, errors[k].second, sizes[k - 1], sizes[k]));
    std::printf("\n");
  }
  const double velocity_rate = rate(errors[1].first, errors[2].first, sizes[1], sizes[2]);
  const double pressure_rate = rate(errors[1].second, errors[2].second, sizes[1], sizes[2]);
  EXPECT_GT(velocity_rate, 1.85) << name;
  EXPECT_GT(pressure_rate, 1.5) << name;
}

// A pressurized shell at rest: a radial force density concentrated on a shell of radius
// R (a membrane under tension pulling inwards), f = P0 s'(r) r̂ with s(r) =
// ½ (1 − tanh((r − R)/w)), given as immersed nodal loads F_J = m_J f(x_J) (m_J the lumped
// mass, as RKPM spreading gives them) in a closed box. The exact solution is rest,
// u = 0, with the pressure p = P0 s(r) + c holding the force. The loads' force density
// in the stabilization's strong residual (coupling.forces_in_stabilization) brings it
// closer to rest: PSPG then weights ∇p − f_h, which vanishes where the pressure balances
// the force; without it PSPG weights ∇p alone and drives a Darcy-like flux τ ∇p through
// the shell. Measured: 3.5-7 times less spurious flow, converging at order 2.5-2.8
// against 1.9 (the shell's width w = 0.05 is under one element at n = 12).
struct ShellAtRest {
  double radius = 0.3, width = 0.05, jump = 1.0;
  static constexpr double centre = 0.5;
  KOKKOS_INLINE_FUNCTION void operator()(const double x[3], double u[3], double& p) const {
    const double dx = x[0] - centre, dy = x[1] - centre, dz = x[2] - centre;
    const double r = sqrt(dx * dx + dy * dy + dz * dz);
    u[0] = u[1] = u[2] = 0.0;
    p = 0.5 * jump * (1.0 - tanh((r - radius) / width));
  }
  // f = ∇p = P0 s'(r) r̂,  s'(r) = −1 / (2 w cosh²((r − R)/w))
  std::array<double, 3> force(const double x[3]) const {
    const double d[3] = {x[0] - centre, x[1] - centre, x[2] - centre};
    const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (r == 0.0) return {0.0, 0.0, 0.0};
    const double c = std::cosh((r - radius) / width);
    const double slope = -0.5 * jump / (width * c * c);
    return {slope * d[0] / r, slope * d[1] / r, slope * d[2] / r};
  }
};

// The shell's force as immersed nodal loads F_J = m_J f(x_J).
ImmersedTerms shell_loads(const FluidMesh& mesh, const ShellAtRest& shell, const FluidSolver& solver,
                          bool in_stabilization) {
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), solver.fluid_operator().lumped_mass());
  Kokkos::View<double*> loads("rouleau::test::shell_loads", mesh.num_unknowns());
  auto host = Kokkos::create_mirror_view(loads);
  for (int node = 0; node < mesh.num_nodes; ++node) {
    const double x[3] = {coordinates(node, 0), coordinates(node, 1), coordinates(node, 2)};
    const int dof_node = mesh.dof_node_of_node[node];
    const auto f = shell.force(x);
    for (int d = 0; d < 3; ++d) host(4 * dof_node + d) = mass(dof_node) * f[d];
  }
  Kokkos::deep_copy(loads, host);
  ImmersedTerms terms;
  terms.loads = loads;
  terms.loads_in_stabilization = in_stabilization;
  return terms;
}

// Solves the closed box with the shell's loads; returns the errors against rest.
FluidErrors shell_at_rest_errors(int n, bool forces_in_stabilization, FluidElementType element) {
  FluidMesh mesh = make_box_mesh({0, 0, 0}, {1, 1, 1}, {n, n, n}, {1, 1, 1}, {false, false, false});
  if (element == FluidElementType::tetrahedron4) mesh = split_into_tetrahedra(mesh);
  FluidSolver solver(mesh, unit_fluid(0.0), std::array<BoundaryConfig, 6>{}, tight_solver(), unit_scales(0.0), true);
  const ShellAtRest shell;
  const FluidSolveReport report = solver.solve_steady(shell_loads(mesh, shell, solver, forces_in_stabilization));
  EXPECT_TRUE(report.converged) << report.failure;
  return fluid_l2_errors(solver.fluid_operator(), solver.state(), shell);
}

TEST(FluidFlows, ImmersedLoadsInTheStabilizationKeepAPressurizedShellAtRest) {
  for (const FluidElementType element : {FluidElementType::hexahedron8, FluidElementType::tetrahedron4}) {
    const char* name = element == FluidElementType::hexahedron8 ? "hexahedra" : "tetrahedra";
    std::vector<double> seepage, seepage_without;
    const std::vector<int> sizes{12, 24};
    for (int n : sizes) {
      const FluidErrors with = shell_at_rest_errors(n, true, element);
      const FluidErrors without = shell_at_rest_errors(n, false, element);
      // L2 norm of the spurious velocity, against the pressure jump's velocity scale
      // P0 R / μ (= 0.3 here, unit viscosity).
      std::printf("shell at rest, %s n = %d: L2 velocity %.3e with the loads in the stabilization, %.3e without "
                  "(ratio %.1f); relative pressure error %.3e with, %.3e without\n",
                  name, n, with.velocity, without.velocity, without.velocity / with.velocity,
                  with.pressure / with.pressure_norm, without.pressure / without.pressure_norm);
      EXPECT_LT(with.velocity, without.velocity / 3.0);
      EXPECT_LT(with.pressure / with.pressure_norm, 0.5 * without.pressure / without.pressure_norm);
      seepage.push_back(with.velocity);
      seepage_without.push_back(without.velocity);
    }
    // Without the loads the spurious flow is τ ∇p, of order h² (τ ∝ h²); with them it is
    // τ (∇p − f_h), and the mismatch falls with h too.
    const double order = rate(seepage[0], seepage[1], sizes[0], sizes[1]);
    const double order_without = rate(seepage_without[0], seepage_without[1], sizes[0], sizes[1]);
    std::printf("shell at rest, %s: spurious velocity falls at order %.2f with the loads in the stabilization, "
                "%.2f without\n", name, order, order_without);
    EXPECT_GT(order, order_without + 0.4);
  }
}

// The flux of a nodal velocity field (4 entries per dof node, scaled) on the uniform
// n³ box mesh of the unit cube through the sphere of radius `radius` about the box's
// centre, its trilinear interpolant integrated by a product rule in (cos θ, φ).
double flux_through_sphere(const FluidMesh& mesh, int n, const Kokkos::View<double*>& field, double radius) {
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto values = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), field);
  std::vector<std::array<double, 3>> grid((n + 1) * (n + 1) * (n + 1));
  const auto at = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int node = 0; node < mesh.num_nodes; ++node) {
    const int i = static_cast<int>(std::lround(coordinates(node, 0) * n));
    const int j = static_cast<int>(std::lround(coordinates(node, 1) * n));
    const int k = static_cast<int>(std::lround(coordinates(node, 2) * n));
    const int dof = mesh.dof_node_of_node[node];
    grid[at(i, j, k)] = {values(4 * dof), values(4 * dof + 1), values(4 * dof + 2)};
  }
  const int polar = 96, azimuthal = 192;
  double flux = 0.0;
  for (int a = 0; a < polar; ++a) {
    const double mu = -1.0 + (a + 0.5) * 2.0 / polar, sine = std::sqrt(1.0 - mu * mu);
    for (int b = 0; b < azimuthal; ++b) {
      const double phi = (b + 0.5) * 2.0 * M_PI / azimuthal;
      const double normal[3] = {sine * std::cos(phi), sine * std::sin(phi), mu};
      double x[3], u[3] = {0, 0, 0};
      int cell[3];
      double t[3];
      for (int d = 0; d < 3; ++d) {
        x[d] = ShellAtRest::centre + radius * normal[d];
        cell[d] = std::min(n - 1, static_cast<int>(x[d] * n));
        t[d] = x[d] * n - cell[d];
      }
      for (int corner = 0; corner < 8; ++corner) {
        const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
        const double w = (di ? t[0] : 1 - t[0]) * (dj ? t[1] : 1 - t[1]) * (dk ? t[2] : 1 - t[2]);
        const auto& value = grid[at(cell[0] + di, cell[1] + dj, cell[2] + dk)];
        for (int d = 0; d < 3; ++d) u[d] += w * value[d];
      }
      flux += (u[0] * normal[0] + u[1] * normal[1] + u[2] * normal[2]) * radius * radius * (2.0 / polar) *
              (2.0 * M_PI / azimuthal);
    }
  }
  return flux;
}

TEST(FluidFlows, SubscaleVelocityCarriesTheFluxThatSeepsThroughAPressurizedShell) {
  // The pressurized shell at rest with its loads as nodal loads only (the Galerkin part):
  // PSPG's flux u' = −τ_M r = −τ_M ∇p points outwards through the shell, and the weak
  // continuity equation makes u_h carry the same flux back in, so a membrane moving with
  // u_h would shrink. The whole velocity u_h + u' (FluidSolver::total_velocity, what the
  // cells move with under coupling.subscale_velocity) has a small fraction of that flux.
  for (const int n : {16, 24}) {
    const FluidMesh mesh = make_box_mesh({0, 0, 0}, {1, 1, 1}, {n, n, n}, {1, 1, 1}, {false, false, false});
    FluidSolver solver(mesh, unit_fluid(0.0), std::array<BoundaryConfig, 6>{}, tight_solver(), unit_scales(0.0), true);
    const ShellAtRest shell;
    const ImmersedTerms loads = shell_loads(mesh, shell, solver, false);
    const FluidSolveReport report = solver.solve_steady(loads);
    ASSERT_TRUE(report.converged) << report.failure;
    Kokkos::View<double*> total("total", mesh.num_unknowns());
    solver.total_velocity(total, loads);
    Kokkos::View<double*> resolved("resolved", mesh.num_unknowns());
    Kokkos::deep_copy(resolved, solver.state());
    for (const double radius : {shell.radius - shell.width, shell.radius, shell.radius + shell.width}) {
      const double seepage = flux_through_sphere(mesh, n, resolved, radius);
      const double whole = flux_through_sphere(mesh, n, total, radius);
      // against the flux scale of the spurious flow, τ ∇p over the sphere: (h²/4)(P0/w) 4πR²
      const double h = 1.0 / n, scale = h * h / 4.0 * shell.jump / shell.width * 4.0 * M_PI * radius * radius;
      std::printf("shell at rest, n = %d, r = %.2f: flux of u_h %.3e, of u_h + u' %.3e (%.1f %% of it; scale %.2e)\n",
                  n, radius, seepage, whole, 100.0 * std::fabs(whole / seepage), scale);
      EXPECT_LT(seepage, -0.05 * scale);  // u_h carries plasma into the shell
      // Measured: 2-23 % (the most at r = R, where u' is sharpest and its lumped projection
      // smears it; 16 % at n = 24).
      EXPECT_LT(std::fabs(whole), 0.25 * std::fabs(seepage));
    }
  }
}

TEST(FluidFlows, Ilu0NeedsFarFewerIterationsThanBlockJacobi) {
  // The same Stokes manufactured problem at 16³ with both preconditioners: both reach the
  // same solution, ILU(0) in at most a third of block Jacobi's GMRES iterations.
  int iterations[2];
  std::pair<double, double> errors[2];
  const PreconditionerType types[2] = {PreconditionerType::block_jacobi, PreconditionerType::ilu0};
  for (int k = 0; k < 2; ++k) errors[k] = manufactured_errors(16, 0.0, true, iterations[k], types[k]);
  std::printf("Stokes MMS 16^3: block Jacobi %d GMRES iterations, ILU(0) %d\n", iterations[0], iterations[1]);
  EXPECT_LT(3 * iterations[1], iterations[0]);
  EXPECT_NEAR(errors[1].first, errors[0].first, 1e-6 * errors[0].first);
}

TEST(FluidFlows, MultigridIterationsBarelyGrowWithTheMesh) {
  // The Stokes manufactured problem at 8³ and 16³ with the aggregation multigrid
  // (W-cycle): the GMRES iterations may grow by at most 1.5× per halving of h,
  // on hexahedra and on tetrahedra, and it reaches ILU(0)'s solution. ILU(0)
  // alone nearly doubles its count (printed for comparison). Measured with the default
  // block-Jacobi smoothing: hexahedra 14, 17 (ILU(0) 22, 41), tetrahedra 16, 22 (ILU(0)
  // 30, 63); with ILU(0) smoothing on aggregates of 8 the multigrid needed 12, 15 and 15,
  // 19. At 24³ ILU(0) alone needs 65 and 103 (2.5 min, so not in the quick tier).
  for (const FluidElementType element : {FluidElementType::hexahedron8, FluidElementType::tetrahedron4}) {
    const char* name = element == FluidElementType::hexahedron8 ? "hexahedra" : "tetrahedra";
    int first = 0;
    for (int n : {8, 16}) {
      int multigrid = 0, ilu = 0;
      const auto errors = manufactured_errors(n, 0.0, true, multigrid, PreconditionerType::multigrid, element);
      const auto reference = manufactured_errors(n, 0.0, true, ilu, PreconditionerType::ilu0, element);
      std::printf("Stokes MMS %d^3 on %s: GMRES iterations with multigrid %d, with ILU(0) %d\n", n, name, multigrid,
                  ilu);
      EXPECT_NEAR(errors.first, reference.first, 1e-5 * reference.first);
      if (n == 8) first = multigrid;
      EXPECT_LE(multigrid, 1.5 * first) << name << ", " << n << "^3";
    }
  }
}

TEST(FluidFlows, MultigridReadingFloatCopiesConvergesAsInDouble) {
  // The Stokes manufactured problem at 16³ with the multigrid's sweeps and residuals
  // reading float copies of the level matrices (the default) and reading the double
  // values: the preconditioner differs by rounding only, so GMRES must reach the same
  // solution (to 1e-5 of the error, as the multigrid reaches ILU(0)'s above) in at
  // most one iteration more.
  for (const FluidElementType element : {FluidElementType::hexahedron8, FluidElementType::tetrahedron4}) {
    const char* name = element == FluidElementType::hexahedron8 ? "hexahedra" : "tetrahedra";
    int single = 0, full = 0;
    const auto errors = manufactured_errors(16, 0.0, true, single, PreconditionerType::multigrid, element,
                                            MultigridPrecision::single_precision);
    const auto reference = manufactured_errors(16, 0.0, true, full, PreconditionerType::multigrid, element,
                                               MultigridPrecision::double_precision);
    std::printf("Stokes MMS 16^3 on %s: GMRES iterations with the multigrid in single precision %d, in double %d; "
                "velocity errors %.6e, %.6e\n",
                name, single, full, errors.first, reference.first);
    EXPECT_LE(single, full + 1) << name;
    EXPECT_NEAR(errors.first, reference.first, 1e-5 * reference.first) << name;
    EXPECT_NEAR(errors.second, reference.second, 1e-5 * reference.second) << name;
  }
}

TEST(FluidFlows, ManufacturedStokesSolutionConverges) {
  check_manufactured_convergence("Stokes MMS", 0.0, true);
}

TEST(FluidFlows, ManufacturedNavierStokesSolutionConverges) {
  check_manufactured_convergence("Navier-Stokes MMS (Re = 10)", 10.0, false);
}

// A residual target below the round-off floor (newton_atol = 0, newton_rtol = 1e-30):
// Newton must stop on its update, ‖δ‖ ≤ newton_step_rtol ‖U‖, at the same solution as a
// reachable target, and fail as before when that stop is turned off.
TEST(FluidFlows, NewtonStopsAtTheResidualsRoundOffFloor) {
  const double reynolds = 10.0;
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {1, 1, 1}, {6, 6, 6}, {1, 1, 1}, {false, false, false});
  const ManufacturedSolution exact{reynolds};
  auto solve = [&](double newton_rtol, double step_rtol, FluidSolveReport& report) {
    SolverConfig settings = tight_solver();
    settings.newton_rtol = newton_rtol;
    settings.newton_atol = 0.0;
    settings.newton_step_rtol = step_rtol;
    FluidSolver solver(mesh, unit_fluid(reynolds), std::array<BoundaryConfig, 6>{}, settings, unit_scales(reynolds),
                       false);
    set_up_manufactured_problem(solver, mesh, exact);
    report = solver.solve_steady();
    return fluid_l2_errors(solver.fluid_operator(), solver.state(), exact).velocity;
  };
  FluidSolveReport reachable, floor, without_stop;
  const double error_reachable = solve(1e-10, 0.0, reachable);
  const double error_floor = solve(1e-30, 1e-8, floor);
  solve(1e-30, 0.0, without_stop);
  std::printf("Newton: %d iterations to 1e-10 of the initial residual; %d to the round-off floor (residual %.2e); "
              "velocity errors %.6e and %.6e\n",
              reachable.newton_iterations, floor.newton_iterations, floor.momentum_residual, error_reachable,
              error_floor);
  ASSERT_TRUE(reachable.converged) << reachable.failure;
  EXPECT_FALSE(reachable.stalled_at_round_off);
  ASSERT_TRUE(floor.converged) << floor.failure;
  EXPECT_TRUE(floor.stalled_at_round_off);
  EXPECT_LT(floor.newton_iterations, SolverConfig{}.newton_max_iterations);
  EXPECT_NEAR(error_floor, error_reachable, 1e-8 * error_reachable);
  EXPECT_FALSE(without_stop.converged);
  EXPECT_NE(without_stop.failure.find("Newton did not converge"), std::string::npos) << without_stop.failure;
}

// The tetrahedral element (vessel meshes) through the same kernels and solver, on the
// same nodes: the same rates are required. Its pressure is much less accurate than the
// hexahedra's (relative 0.35 against 0.006 at n = 24): along the box's edges Kuhn's cut
// leaves tetrahedra with all four nodes on the Dirichlet boundary, whose pressure only the
// stabilization sets, with a viscous term from one-sided projected gradients. The
// velocity is as accurate as on hexahedra.
TEST(FluidFlows, ManufacturedStokesSolutionConvergesOnTetrahedra) {
  check_manufactured_convergence("Stokes MMS on tetrahedra", 0.0, true, FluidElementType::tetrahedron4);
}

TEST(FluidFlows, ManufacturedNavierStokesSolutionConvergesOnTetrahedra) {
  check_manufactured_convergence("Navier-Stokes MMS (Re = 10) on tetrahedra", 10.0, false,
                                 FluidElementType::tetrahedron4);
}

}  // namespace
}  // namespace rouleau

namespace rouleau {
namespace {

// A decaying shear wave in a fully periodic box: u_x = sin(2πy) e^(−4π² t/Re) solves
// Re ∂u/∂t = Δu, ∇p = 0. The time error is measured against a run on the same mesh with
// a 64 times smaller step (so the spatial error cancels): backward Euler must converge at
// first order, BDF2 at second.
std::vector<double> shear_wave_velocity(TimeScheme scheme, int steps, double end_time) {
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {1, 1, 1}, {2, 16, 2}, {1, 1, 1}, {true, true, true});
  std::array<BoundaryConfig, 6> sides{};
  for (auto& s : sides) s.type = BoundaryType::periodic;
  FluidSolver solver(mesh, unit_fluid(1.0), sides, tight_solver(), unit_scales(1.0), true);
  solver.set_velocity([](const std::array<double, 3>& x) {
    return std::array<double, 3>{std::sin(2.0 * 3.14159265358979323846 * x[1]), 0.0, 0.0};
  });
  for (int step = 0; step < steps; ++step) {
    const FluidSolveReport report = solver.advance(end_time / steps, scheme);
    EXPECT_TRUE(report.converged) << report.failure;
  }
  std::vector<double> velocity, pressure;
  solver.velocity_and_pressure(velocity, pressure);
  return velocity;
}

double rms_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / a.size());
}

TEST(FluidFlows, TimeSteppingConvergesAtTheSchemesOrder) {
  const double end_time = 0.02;  // the wave decays by e^(−0.79)
  const auto reference = shear_wave_velocity(TimeScheme::bdf2, 512, end_time);
  for (const auto& [scheme, name, order] : {std::tuple{TimeScheme::backward_euler, "backward Euler", 1.0},
                                            std::tuple{TimeScheme::bdf2, "BDF2", 2.0}}) {
    std::vector<double> errors;
    const std::vector<int> steps{8, 16, 32};
    for (int n : steps) errors.push_back(rms_difference(shear_wave_velocity(scheme, n, end_time), reference));
    const double r1 = rate(errors[0], errors[1], steps[0], steps[1]), r2 = rate(errors[1], errors[2], steps[1], steps[2]);
    std::printf("%s: errors %.3e %.3e %.3e at 8/16/32 steps, rates %.2f %.2f\n", name, errors[0], errors[1], errors[2],
                r1, r2);
    EXPECT_NEAR(r2, order, 0.15) << name;
  }
}

// Two superposed shear waves decaying at rates 4π² and 16π² (Re = 1): every BDF2 solution
// lies in the span of the two modes, so the least-residual combination of the last
// solutions (fluid_starting_guess.cpp) starts each step almost at its answer, where the
// linear extrapolation 2 U^n − U^{n−1} is off by O(Δt²). Checked: the same velocities as
// with the extrapolation (to the solver's tolerance) in at most half its GMRES iterations
// over steps 4–12; the bound was written before the run.
std::pair<std::vector<double>, int> two_wave_run(int starting_guess_solutions) {
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {1, 1, 1}, {2, 16, 2}, {1, 1, 1}, {true, true, true});
  std::array<BoundaryConfig, 6> sides{};
  for (auto& s : sides) s.type = BoundaryType::periodic;
  SolverConfig settings = tight_solver();
  settings.starting_guess_solutions = starting_guess_solutions;
  FluidSolver solver(mesh, unit_fluid(1.0), sides, settings, unit_scales(1.0), true);
  solver.set_velocity([](const std::array<double, 3>& x) {
    const double k = 2.0 * 3.14159265358979323846;
    return std::array<double, 3>{std::sin(k * x[1]) + 0.5 * std::cos(2.0 * k * x[1]), 0.0, 0.0};
  });
  int late_iterations = 0;
  for (int step = 1; step <= 12; ++step) {
    const FluidSolveReport report = solver.advance(0.002, TimeScheme::bdf2);
    EXPECT_TRUE(report.converged) << report.failure;
    if (step >= 4) late_iterations += report.gmres_iterations;
  }
  std::vector<double> velocity, pressure;
  solver.velocity_and_pressure(velocity, pressure);
  return {velocity, late_iterations};
}

TEST(FluidFlows, ProjectedStartingGuessSavesIterationsAndKeepsTheAnswer) {
  const auto [extrapolated, extrapolated_iterations] = two_wave_run(0);
  const auto [projected, projected_iterations] = two_wave_run(4);
  const double difference = rms_difference(projected, extrapolated);
  std::printf("two decaying waves, steps 4-12: GMRES %d iterations from the projected guess, %d from the "
              "extrapolated one; rms velocity difference %.2e\n",
              projected_iterations, extrapolated_iterations, difference);
  EXPECT_LT(difference, 1e-8);
  EXPECT_LE(2 * projected_iterations, extrapolated_iterations);
}

}  // namespace
}  // namespace rouleau
