// The uniform-box stencil path of the Stokes operator (fluid/uniform_box_stencil.hpp)
// against the element-by-element path, its reference: the same Aδ to round-off on boxes
// with walls, periodic sides, anisotropic elements, with and without the viscous
// reconstruction, steady and transient, and after the time step changes.
#include <gtest/gtest.h>

#include <Kokkos_Random.hpp>

#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_operator.hpp"
#include "fluid/fluid_solver.hpp"
#include "mesh/fluid_mesh.hpp"
#include "test_helpers.hpp"
#include "unit_fluid.hpp"

namespace rouleau {
namespace {

struct StencilCase {
  const char* name;
  std::array<int, 3> elements;
  std::array<bool, 3> periodic;
};

FluidCoefficients stokes_coefficients(double dt, int viscous_reconstruction) {
  FluidCoefficients c;
  c.reynolds = 0.7;
  c.convection = 0;
  c.viscous_reconstruction = viscous_reconstruction;
  c.mass_coefficient = dt > 0 ? 1.5 / dt : 0.0;
  c.inverse_dt = dt > 0 ? 1.0 / dt : 0.0;
  return c;
}

// The box 2 × 1 × 1.5 (elements anisotropic unless the counts say otherwise), in the
// operator's scaled length 0.8, with walls where a side is not periodic: a moving lid at
// y_max and no slip elsewhere.
FluidBoundaryConditions walls_and_lid(const FluidMesh& mesh, const std::array<bool, 3>& periodic) {
  std::array<BoundaryConfig, 6> sides{};
  for (int d = 0; d < 3; ++d)
    if (periodic[d]) sides[2 * d].type = sides[2 * d + 1].type = BoundaryType::periodic;
  sides[Side::y_max].velocity = {1.0, 0.0, 0.5};
  return build_boundary_conditions(mesh, sides, FluidScales{});
}

// Aδ on the stencil path and on the element path, for a random δ.
void expect_paths_agree(FluidOperator& op, const FluidCoefficients& c, std::uint64_t seed) {
  op.set_coefficients(c);
  Vector direction("direction", op.num_unknowns()), stencil("stencil", op.num_unknowns()),
      elements("elements", op.num_unknowns());
  Kokkos::Random_XorShift64_Pool<> pool(seed);
  Kokkos::fill_random(direction, pool, -1.0, 1.0);
  op.allow_stencil(true);
  ASSERT_TRUE(op.uses_stencil()) << op.stencil_unavailable_reason();
  op.linear_action(direction, stencil);
  op.allow_stencil(false);
  ASSERT_FALSE(op.uses_stencil());
  op.linear_action(direction, elements);
  op.allow_stencil(true);
  testing::expectAllClose(stencil, elements, 1e-12, 1e-12);
}

class UniformBoxStencil : public ::testing::TestWithParam<StencilCase> {};

TEST_P(UniformBoxStencil, MatchesTheElementPathToRoundOff) {
  const StencilCase& box = GetParam();
  const FluidMesh mesh = make_box_mesh({0.0, 0.0, 0.0}, {2.0, 1.0, 1.5}, box.elements, {1.0, 1.0, 1.0}, box.periodic);
  FluidOperator op(mesh, 0.8);
  const auto bc = walls_and_lid(mesh, box.periodic);
  op.set_dirichlet(bc.dirichlet_dofs, bc.dirichlet_values);
  std::uint64_t seed = 7;
  for (int viscous : {0, 1})
    for (double dt : {0.0, 0.05}) {
      SCOPED_TRACE(::testing::Message() << "viscous_reconstruction " << viscous << ", dt " << dt);
      expect_paths_agree(op, stokes_coefficients(dt, viscous), ++seed);
    }
  // A new time step changes the mass and τ terms: the tables follow.
  SCOPED_TRACE("after the time step changed");
  expect_paths_agree(op, stokes_coefficients(0.02, 1), ++seed);
}

INSTANTIATE_TEST_SUITE_P(
    Boxes, UniformBoxStencil,
    ::testing::Values(StencilCase{"Walls", {4, 3, 5}, {false, false, false}},
                      StencilCase{"ShearBox", {5, 4, 3}, {true, false, true}},
                      StencilCase{"Periodic", {3, 3, 4}, {true, true, true}},
                      StencilCase{"OneElementThick", {4, 3, 1}, {false, false, true}},
                      StencilCase{"TwoElementsPeriodic", {2, 3, 2}, {true, false, true}}),
    [](const ::testing::TestParamInfo<StencilCase>& info) { return std::string(info.param.name); });

TEST(UniformBoxStencilUse, NotUsedWhereElementsDiffer) {
  const FluidMesh graded = make_box_mesh({0, 0, 0}, {2, 1, 1}, {4, 4, 2}, {1.0, 1.5, 1.0}, {true, false, true});
  FluidOperator on_graded(graded, 1.0);
  on_graded.set_coefficients(stokes_coefficients(0.1, 1));
  EXPECT_FALSE(on_graded.uses_stencil());
  EXPECT_NE(on_graded.stencil_unavailable_reason().find("graded"), std::string::npos)
      << on_graded.stencil_unavailable_reason();

  const FluidMesh uniform = make_box_mesh({0, 0, 0}, {2, 1, 1}, {4, 4, 2}, {1.0, 1.0, 1.0}, {true, false, true});
  FluidOperator on_tetrahedra(split_into_tetrahedra(uniform), 1.0);
  on_tetrahedra.set_coefficients(stokes_coefficients(0.1, 1));
  EXPECT_FALSE(on_tetrahedra.uses_stencil());

  FluidOperator navier_stokes(uniform, 1.0);
  FluidCoefficients c = stokes_coefficients(0.1, 1);
  c.convection = 1;
  navier_stokes.set_coefficients(c);
  EXPECT_FALSE(navier_stokes.uses_stencil());
  EXPECT_NE(navier_stokes.stencil_unavailable_reason().find("convective"), std::string::npos);
  c.convection = 0;
  navier_stokes.set_coefficients(c);
  EXPECT_TRUE(navier_stokes.uses_stencil()) << navier_stokes.stencil_unavailable_reason();
}

// The start-up of plane Poiseuille flow in a shear box (walls at y = 0 and 1, body force
// 8 μU/H², Stokes), three BDF steps through FluidSolver on each path: GMRES sees the same
// operator, so the states agree to its tolerance and the iteration counts match.
TEST(UniformBoxStencilUse, SolverGivesTheSameTransientFlowOnBothPaths) {
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {2, 1, 1}, {6, 8, 4}, {1, 1, 1}, {true, false, true});
  std::array<BoundaryConfig, 6> sides{};
  sides[Side::x_min].type = sides[Side::x_max].type = BoundaryType::periodic;
  sides[Side::z_min].type = sides[Side::z_max].type = BoundaryType::periodic;
  FluidConfig fluid = testing::unit_fluid(0.5);
  fluid.body_force = {8.0, 0.0, 0.0};
  std::vector<Vector> states;
  std::vector<int> iterations;
  for (bool stencil : {true, false}) {
    FluidSolver solver(mesh, fluid, sides, testing::tight_solver(), testing::unit_scales(0.5), true);
    solver.allow_stencil(stencil);
    int total = 0;
    for (int step = 0; step < 3; ++step) {
      const FluidSolveReport report = solver.advance(0.02, TimeScheme::bdf2);
      ASSERT_TRUE(report.converged) << report.failure;
      total += report.gmres_iterations;
    }
    EXPECT_EQ(solver.fluid_operator().uses_stencil(), stencil);
    Vector state("state", solver.state().extent(0));
    Kokkos::deep_copy(state, solver.state());
    states.push_back(state);
    iterations.push_back(total);
  }
  std::printf("GMRES iterations over three steps: stencil %d, element by element %d\n", iterations[0], iterations[1]);
  testing::expectAllClose(states[0], states[1], 1e-8, 1e-9);
  EXPECT_NEAR(iterations[0], iterations[1], 1);
}

}  // namespace
}  // namespace rouleau
