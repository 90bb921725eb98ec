// The fast diagonalization of a periodic box's Stokes operator (fluid/fast_diagonalization.hpp)
// against the property that defines it: it is the operator's exact inverse up to the
// pressure pin (a rank-one difference) and the zero wave number's pressure level (another),
// so GMRES preconditioned with it converges in at most 3 iterations on any right-hand side,
// to the same answer as with the multigrid. Checked on boxes whose walls lie across y and
// across z, with even and odd numbers of elements along the periodic axes (the real
// transform's halved axis has a Nyquist wave number only when even), one graded toward its
// walls (the blocks are read off the operator, so grading across the walls is allowed), one
// with an inflow and a traction side instead of walls (no pressure pin), and a case file
// that asks for it where it does not apply is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "config/load_case.hpp"
#include "fluid/fast_diagonalization.hpp"
#include "fluid/fluid_solver.hpp"
#include "unit_fluid.hpp"
#include "util/errors.hpp"

namespace rouleau {
namespace {

using testing::tight_solver;
using testing::unit_fluid;
using testing::unit_scales;

struct BoxRun {
  std::vector<double> velocity, pressure;
  int most_iterations = 0;  // GMRES iterations of the costliest step
};

// A Stokes box periodic along two axes, walls across `wall_axis` (the upper one sliding
// along the next axis), started from a velocity with many wave numbers; 4 BDF2 steps.
BoxRun periodic_box_run(PreconditionerType preconditioner, int wall_axis, const std::array<int, 3>& elements,
                        double wall_grading, bool open) {
  std::array<bool, 3> periodic{true, true, true};
  periodic[wall_axis] = false;
  std::array<double, 3> grading{1, 1, 1};
  grading[wall_axis] = wall_grading;
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {1.0, 0.8, 1.2}, elements, grading, periodic);
  std::array<BoundaryConfig, 6> sides{};
  for (int axis = 0; axis < 3; ++axis)
    if (periodic[axis]) sides[2 * axis].type = sides[2 * axis + 1].type = BoundaryType::periodic;
  sides[2 * wall_axis + 1].velocity[(wall_axis + 1) % 3] = 1.0;
  if (open) {  // a uniform inflow through the lower side, out through a traction side: no pressure pin
    sides[2 * wall_axis].type = BoundaryType::inflow;
    sides[2 * wall_axis].mean_speed = 1.0;
    sides[2 * wall_axis].profile = InflowProfile::uniform;
    sides[2 * wall_axis + 1].type = BoundaryType::traction;
  }
  SolverConfig settings = tight_solver();
  settings.preconditioner = preconditioner;
  settings.starting_guess_solutions = 0;
  FluidSolver solver(mesh, unit_fluid(1.0), sides, settings, unit_scales(1.0), true);
  solver.set_velocity([](const std::array<double, 3>& x) {
    const double k = 2.0 * 3.14159265358979323846;
    return std::array<double, 3>{std::sin(k * x[1]) * std::cos(k * x[2]) + 0.3 * std::cos(2.0 * k * x[0]),
                                 0.5 * std::sin(k * (x[0] + x[2])), std::cos(k * x[0]) * std::sin(3.0 * k * x[1])};
  });
  BoxRun run;
  for (int step = 1; step <= 4; ++step) {
    const FluidSolveReport report = solver.advance(0.01, TimeScheme::bdf2);
    EXPECT_TRUE(report.converged) << report.failure;
    run.most_iterations = std::max(run.most_iterations, report.gmres_iterations);
  }
  solver.velocity_and_pressure(run.velocity, run.pressure);
  return run;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::fabs(a[i] - b[i]));
  return largest;
}

TEST(FastDiagonalization, InvertsThePeriodicStokesOperatorUpToThePressurePin) {
  struct Box {
    int wall_axis;
    std::array<int, 3> elements;
    double wall_grading;  // refinement toward the walls (the periodic axes stay uniform)
    bool open = false;    // inflow and traction sides instead of walls
  };
  const std::array<int, 3> small{8, 6, 6};
  if (!FastDiagonalization::unavailable_reason(make_box_mesh({0, 0, 0}, {1, 1, 1}, small, {1, 1, 1},
                                                             {true, false, true}))
           .empty())
    GTEST_SKIP() << "the fast diagonalization does not run in this build (the fluid's vectors live on a GPU)";
  for (const Box& box : {Box{1, small, 1.0}, Box{1, {7, 5, 6}, 1.0}, Box{2, {6, 5, 7}, 1.0}, Box{1, {6, 6, 6}, 1.5},
                         Box{1, {6, 6, 6}, 1.0, true}}) {
    const BoxRun fast =
        periodic_box_run(PreconditionerType::fast_diagonalization, box.wall_axis, box.elements, box.wall_grading,
                         box.open);
    const BoxRun multigrid =
        periodic_box_run(PreconditionerType::multigrid, box.wall_axis, box.elements, box.wall_grading, box.open);
    const double velocity_difference = largest_difference(fast.velocity, multigrid.velocity);
    // The pressure's level is pinned at one node in both: compare it as it is.
    const double pressure_difference = largest_difference(fast.pressure, multigrid.pressure);
    std::printf("%s across axis %d (grading %.1f), %d x %d x %d elements: GMRES at most %d iterations per step "
                "(multigrid %d); largest difference of the velocity %.2e, of the pressure %.2e\n",
                box.open ? "inflow and outflow" : "walls", box.wall_axis, box.wall_grading, box.elements[0], box.elements[1], box.elements[2], fast.most_iterations,
                multigrid.most_iterations, velocity_difference, pressure_difference);
    EXPECT_LE(fast.most_iterations, 3);
    EXPECT_LT(velocity_difference, 1e-7);
    EXPECT_LT(pressure_difference, 1e-6);
  }
}

TEST(FastDiagonalization, IsRefusedWhereTheBoxIsNotPeriodicAlongTwoAxes) {
  const std::string channel = R"(
[case]
name = "channel"
[fluid]
viscosity_Pa_s = 1.2e-3
[domain]
lower_um = [0.0, 0.0, 0.0]
upper_um = [10.0, 4.0, 4.0]
elements = [10, 4, 4]
[boundary.x_min]
type = "traction"
pressure_Pa = 0.06
[boundary.x_max]
type = "traction"
pressure_Pa = 0.0
[boundary.z_min]
type = "periodic"
[boundary.z_max]
type = "periodic"
[time]
dt_s = 0.01
end_s = 0.02
[solver]
preconditioner = "fast_diagonalization"
)";
  try {
    load_case_text(channel, "channel.toml");
    FAIL() << "a channel periodic along one axis was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("solver.preconditioner"), std::string::npos) << message;
    EXPECT_NE(message.find("periodic along 1 axes"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace rouleau
