// A distributed GMRES solve on 2 (or more) MPI ranks (issue 10): the Stokes system of the
// shear box (moving walls at y = ±5 μm, periodic in x and z, the pressure pinned at one
// node) with a manufactured right-hand side b = A x*, solved with point-block Jacobi to
// 1e-10 by one rank and by all ranks together. The distributed solve must take the same
// number of iterations (its sums differ only in order, ±1 allowed) and give the one-rank
// solution to 1e-9 of its size.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <Kokkos_Random.hpp>
#include <cmath>
#include <cstdio>
#include <vector>

#include "distributed/distributed_fluid_operator.hpp"
#include "distributed/local_mesh.hpp"
#include "distributed/node_halo.hpp"
#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_operator.hpp"
#include "parallel/communicator.hpp"
#include "solver/block_jacobi.hpp"
#include "solver/gmres.hpp"

namespace rouleau {
namespace {

// The global Stokes operator A with its Dirichlet rows, as LinearOperator for GMRES.
class GlobalStokes final : public LinearOperator {
 public:
  explicit GlobalStokes(const FluidOperator& op) : op_(op) {}
  void apply(const Kokkos::View<const double*>& x, const Kokkos::View<double*>& y) const override {
    op_.linear_action(x, y);
  }

 private:
  const FluidOperator& op_;
};

TEST(DistributedGmres, SolvesTheStokesSystemAsOneRankDoes) {
  const Communicator world = Communicator::world();
  const FluidMesh mesh = make_box_mesh({0, -5, 0}, {12, 5, 6}, {12, 6, 6}, {1.0, 1.3, 1.0}, {true, false, true});
  std::array<BoundaryConfig, 6> sides{};
  sides[Side::x_min].type = sides[Side::x_max].type = BoundaryType::periodic;
  sides[Side::z_min].type = sides[Side::z_max].type = BoundaryType::periodic;
  sides[Side::y_min].velocity = {-1.0, 0.0, 0.0};
  sides[Side::y_max].velocity = {1.0, 0.0, 0.0};
  const FluidBoundaryConditions bc = build_boundary_conditions(mesh, sides, FluidScales{});
  ASSERT_TRUE(bc.pressure_pinned);
  FluidCoefficients c;
  c.convection = 0;
  c.reynolds = 1e-3;
  c.mass_coefficient = 1.5 / 0.05;
  c.inverse_dt = 1.0 / 0.05;
  const int n = mesh.num_unknowns();
  GmresSettings settings;
  settings.relative_tolerance = 1e-10;
  settings.restart = 40;

  // One rank: A, b = A x*, block Jacobi, GMRES from zero.
  FluidOperator global(mesh, 1.0);
  global.set_coefficients(c);
  global.set_dirichlet(bc.dirichlet_dofs, bc.dirichlet_values);
  Vector exact("exact", n), b("b", n), zero_state("zero_state", n), blocks("blocks", 16 * mesh.num_dof_nodes);
  Kokkos::Random_XorShift64_Pool<> pool(77);
  Kokkos::fill_random(exact, pool, -1.0, 1.0);
  global.linear_action(exact, b);
  global.diagonal_blocks(zero_state, blocks);
  BlockJacobi jacobi(mesh.num_dof_nodes);
  ASSERT_EQ(jacobi.factor(blocks), 0);
  Vector one_rank("one_rank", n);
  Gmres serial(n, settings);
  const GmresResult serial_result = serial.solve(GlobalStokes(global), jacobi, b, one_rank);
  ASSERT_TRUE(serial_result.converged);

  // All ranks: the rank's elements, its owned share of b.
  const ElementPartition partition = partition_fluid_mesh(mesh, world.rank(), world.size());
  FluidOperator local(make_local_mesh(mesh, partition), 1.0);
  local.set_coefficients(c);
  const NodeHalo halo(world, partition, 4);
  const std::vector<int> dirichlet = owned_local_unknowns(partition, bc.dirichlet_dofs);
  const DistributedStokesOperator A(local, halo, partition, dirichlet);
  DistributedBlockJacobi preconditioner(world, partition, dirichlet);
  Vector local_zero("local_zero", 4 * partition.num_local_nodes());
  ASSERT_EQ(preconditioner.factor(local, local_zero), 0);
  const int owned = A.num_owned_unknowns();
  const auto b_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), b);
  Vector b_owned("b_owned", owned), x_owned("x_owned", owned);
  {
    auto h = Kokkos::create_mirror_view(b_owned);
    for (int l = 0; l < partition.num_owned_nodes; ++l)
      for (int k = 0; k < 4; ++k) h(4 * l + k) = b_host(4 * partition.global_node[l] + k);
    Kokkos::deep_copy(b_owned, h);
  }
  Gmres distributed(owned, settings, &world);
  const GmresResult result = distributed.solve(A, preconditioner, b_owned, x_owned);

  // Against the one-rank solution and x*, over all ranks.
  const auto x_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x_owned);
  const auto serial_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), one_rank);
  const auto exact_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), exact);
  double from_serial = 0.0, from_exact = 0.0, size = 0.0, serial_from_exact = 0.0;
  for (int l = 0; l < partition.num_owned_nodes; ++l)
    for (int k = 0; k < 4; ++k) {
      const int g = 4 * partition.global_node[l] + k;
      from_serial += std::pow(x_host(4 * l + k) - serial_host(g), 2);
      from_exact += std::pow(x_host(4 * l + k) - exact_host(g), 2);
      size += exact_host(g) * exact_host(g);
    }
  for (int i = 0; i < n; ++i) serial_from_exact += std::pow(serial_host(i) - exact_host(i), 2);
  const double norm = std::sqrt(world.sum(size));
  from_serial = std::sqrt(world.sum(from_serial)) / norm;
  from_exact = std::sqrt(world.sum(from_exact)) / norm;
  serial_from_exact = std::sqrt(serial_from_exact) / norm;
  if (world.rank() == 0)
    std::printf("Stokes, %d unknowns, block Jacobi: one rank %d GMRES iterations, %d ranks %d; distributed vs "
                "one-rank solution %.2e; error against x*: %.3e (%d ranks), %.3e (one rank)\n",
                n, serial_result.iterations, world.size(), result.iterations, from_serial, from_exact, world.size(),
                serial_from_exact);
  EXPECT_TRUE(result.converged);
  EXPECT_NEAR(result.iterations, serial_result.iterations, 1);
  EXPECT_LT(from_serial, 1e-9);
  // Both solutions are as far from x* as the tolerance and the system's conditioning allow
  // (2.5e-7 at 1e-10): the distributed one no farther than the one-rank one and their gap.
  EXPECT_LE(from_exact, serial_from_exact + from_serial);
}

}  // namespace
}  // namespace rouleau
