// The distributed fluid operator on 2 (or more) MPI ranks: the shared nodes'
// exchange (NodeHalo) and the rank-local operators give the single-rank answer to
// round-off. Every rank also builds the whole mesh and its operator, the reference.
// Also the gather of whole vectors on one rank for output and checkpoints (RootGather), and
// the replication of whole vectors on every rank for the cells (FluidDistribution).
// Run by ctest as `mpiexec -n 2 mpi_halo` (oversubscribed where the machine has fewer cores).
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "distributed/fluid_distribution.hpp"
#include "distributed/local_mesh.hpp"
#include "distributed/node_halo.hpp"
#include "distributed/node_sums.hpp"
#include "distributed/root_gather.hpp"
#include "fluid/fluid_operator.hpp"
#include "parallel/communicator.hpp"
#include "partitioned_meshes.hpp"
#include "util/view_transfer.hpp"

namespace rouleau {
namespace {

using testing::partition_name;
using testing::partitioned_meshes;
using testing::shear_box;

using HostVector = Kokkos::View<double*, Kokkos::HostSpace>;

struct Distributed {
  explicit Distributed(FluidMesh mesh_ = shear_box()) : mesh(std::move(mesh_)) {}
  Communicator world = Communicator::world();
  FluidMesh mesh;
  ElementPartition partition = partition_fluid_mesh(mesh, world.rank(), world.size());
  FluidMesh local_mesh = make_local_mesh(mesh, partition);
  NodeHalo halo{world, partition, 4};

  // The rank's part of a global vector; `copies_too` false leaves the copies at −1e300
  // (what an exchange must overwrite).
  Vector local_part(const HostVector& global, bool copies_too = true) const {
    Vector local("local", 4 * partition.num_local_nodes());
    auto h = Kokkos::create_mirror_view(local);
    for (int l = 0; l < partition.num_local_nodes(); ++l)
      for (int c = 0; c < 4; ++c)
        h(4 * l + c) = copies_too || l < partition.num_owned_nodes ? global(4 * partition.global_node[l] + c) : -1e300;
    Kokkos::deep_copy(local, h);
    return local;
  }
  // The largest |local − global| over all local entries, and over all ranks.
  double largest_difference(const Vector& local, const HostVector& global) const {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), local);
    double largest = 0.0;
    for (int l = 0; l < partition.num_local_nodes(); ++l)
      for (int c = 0; c < 4; ++c)
        largest = std::fmax(largest, std::fabs(h(4 * l + c) - global(4 * partition.global_node[l] + c)));
    return world.max(largest);
  }
};

// The same on every rank: drawn on the host in order (a device fill_random hands out its
// generator states by thread, which differs between ranks on a GPU).
HostVector random_vector(int n, unsigned seed) {
  HostVector v("random", n);
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int i = 0; i < n; ++i) v(i) = uniform(generator);
  return v;
}

// Re 2, a step of 0.1 (scaled), Navier–Stokes or Stokes, with or without the viscous
// reconstruction.
FluidCoefficients transient_coefficients(int convection, int viscous_reconstruction) {
  FluidCoefficients c;
  c.reynolds = 2.0;
  c.mass_coefficient = 1.5 / 0.1;
  c.inverse_dt = 1.0 / 0.1;
  c.convection = convection;
  c.viscous_reconstruction = viscous_reconstruction;
  return c;
}

// The whole mesh's action on one rank: the Navier–Stokes Jacobian action at `state` along
// `direction` (convection on) or the Stokes action (off), and its largest entry.
struct WholeMeshAction {
  HostVector values;
  double largest = 0.0;
};
WholeMeshAction whole_mesh_action(const FluidMesh& mesh, const FluidCoefficients& c, const HostVector& state,
                                  const HostVector& direction) {
  const int n = mesh.num_unknowns();
  FluidOperator global(mesh, 1.0);
  global.allow_stencil(false);
  global.set_coefficients(c);
  Vector global_state("global_state", n), global_direction("global_direction", n), expected("expected", n);
  Kokkos::deep_copy(global_state, state);
  Kokkos::deep_copy(global_direction, direction);
  if (c.convection)
    global.jacobian_action(global_state, global_direction, expected);
  else
    global.linear_action(global_direction, expected);
  WholeMeshAction result{Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), expected), 0.0};
  for (int i = 0; i < n; ++i) result.largest = std::fmax(result.largest, std::fabs(result.values(i)));
  return result;
}

TEST(NodeHalo, EveryCopyTakesItsOwnersValue) {
  Distributed d;
  HostVector ids("ids", d.mesh.num_unknowns());
  for (int i = 0; i < d.mesh.num_unknowns(); ++i) ids(i) = i;
  const Vector local = d.local_part(ids, false);
  d.halo.update_copies(local);
  EXPECT_EQ(d.largest_difference(local, ids), 0.0);
  if (d.world.rank() == 0)
    std::printf("%d ranks: %d of %d dof nodes owned on rank 0, %lld values per update\n", d.world.size(),
                d.partition.num_owned_nodes, d.mesh.num_dof_nodes, d.halo.values_per_update());
  EXPECT_EQ(d.world.sum(static_cast<long long>(d.partition.num_owned_nodes)), d.mesh.num_dof_nodes);
}

TEST(NodeHalo, SumIntoOwnersCountsEveryElementOfANode) {
  // Each rank counts its elements at each of its nodes; summed at the owners (and sent
  // back to the copies) that is every node's element count in the whole mesh.
  Distributed d;
  auto global_connectivity = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), d.mesh.element_dof_nodes);
  HostVector valence("valence", d.mesh.num_unknowns());
  for (int e = 0; e < d.mesh.num_elements; ++e)
    for (int a = 0; a < d.mesh.nodes_per_element; ++a)
      for (int c = 0; c < 4; ++c) valence(4 * global_connectivity(e, a) + c) += 1.0;
  auto local_connectivity = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), d.local_mesh.element_dof_nodes);
  Vector counts("counts", 4 * d.partition.num_local_nodes());
  auto h = Kokkos::create_mirror_view(counts);
  for (int e = 0; e < d.local_mesh.num_elements; ++e)
    for (int a = 0; a < d.local_mesh.nodes_per_element; ++a)
      for (int c = 0; c < 4; ++c) h(4 * local_connectivity(e, a) + c) += 1.0;
  Kokkos::deep_copy(counts, h);
  d.halo.sum_into_owners(counts);
  EXPECT_EQ(d.largest_difference(counts, valence), 0.0);
}

TEST(NodeHalo, DistributedOperatorsGiveTheSingleRankAnswer) {
  // y = Σ_e K_e x on each rank's elements, summed into the owners, against the global
  // operator: the Stokes action and the Navier–Stokes Jacobian action (the state's copies
  // filled by update_copies), to 1e-13 of the largest entry; the distributed dot product
  // against the global one. On the box's blocks and on a METIS partition of its tetrahedra.
  for (const FluidMesh& mesh : partitioned_meshes()) {
  Distributed d(mesh);
  const int n = d.mesh.num_unknowns();
  const HostVector state = random_vector(n, 11), direction = random_vector(n, 12);
  for (const int convection : {0, 1}) {
    const FluidCoefficients c = transient_coefficients(convection, 0);
    const WholeMeshAction expected = whole_mesh_action(d.mesh, c, state, direction);
    FluidOperator local(d.local_mesh, 1.0);
    local.set_coefficients(c);
    const Vector local_state = d.local_part(state, false), local_direction = d.local_part(direction, false);
    d.halo.update_copies(local_state);
    d.halo.update_copies(local_direction);
    Vector action("action", local_state.extent(0));
    if (convection)
      local.jacobian_action(local_state, local_direction, action);
    else
      local.linear_action(local_direction, action);
    d.halo.sum_into_owners(action);
    const double largest = expected.largest;
    const double difference = d.largest_difference(action, expected.values);
    const double dot = d.halo.dot(action, local_direction);
    double expected_dot = 0.0;
    for (int i = 0; i < n; ++i) expected_dot += expected.values(i) * direction(i);
    if (d.world.rank() == 0)
      std::printf("%s, %s on %d ranks: largest difference from one rank %.2e (of entries up to %.3g); <y, x> %.17g "
                  "vs %.17g\n",
                  partition_name(mesh), convection ? "Navier-Stokes Jacobian action" : "Stokes action", d.world.size(),
                  difference, largest,
                  dot, expected_dot);
    EXPECT_LT(difference, 1e-13 * largest);
    EXPECT_NEAR(dot, expected_dot, 1e-12 * std::fabs(expected_dot));
  }
  }
}

TEST(NodeSums, MakeTheRankOperatorsWholeWithTheViscousReconstruction) {
  // The Navier–Stokes Jacobian action and the Stokes action with the viscous reconstruction (the projected
  // gradient in the strong residual: a lumped L2 projection, whose element sums and mass at
  // a shared node need the other ranks' elements), on the box's blocks and on a METIS
  // partition of its tetrahedra. With the operator's node sums every local entry, owned or
  // copy, is the global one to 1e-13 of the largest, whether the exchanges (the ghost
  // exchange of the direction's copies among them) travel while the interior elements are
  // summed (the default) or complete before the loop goes on; without them the shared
  // nodes are off. The point-block diagonal (16 values per node) the same way.
  for (const FluidMesh& mesh : partitioned_meshes()) {
    Distributed d(mesh);
    const int n = d.mesh.num_unknowns();
    const HostVector state = random_vector(n, 31), direction = random_vector(n, 32);
    for (const int convection : {1, 0}) {
    const FluidCoefficients c = transient_coefficients(convection, 1);
    const WholeMeshAction expected = whole_mesh_action(d.mesh, c, state, direction);
    if (d.world.size() > 1) {  // both kinds of element on every rank: the overlap has work to hide behind
      EXPECT_GT(d.partition.num_boundary_elements, 0);
      EXPECT_LT(d.partition.num_boundary_elements, static_cast<int>(d.partition.elements.size()));
    }
    enum Sums { none, after_the_loop, overlapped };
    double differences[3];
    Vector actions[3], blocks[3];
    for (const Sums sums_mode : {none, after_the_loop, overlapped}) {
      FluidOperator local(d.local_mesh, 1.0);
      local.set_coefficients(c);
      NodeSums sums(d.world, d.partition);
      sums.set_overlap(sums_mode == overlapped);
      if (sums_mode != none) local.set_node_sums(&sums);
      Vector& action = actions[sums_mode] = Vector("action", 4 * d.partition.num_local_nodes());
      blocks[sums_mode] = Vector("blocks", 16 * d.partition.num_local_nodes());
      // the direction's copies left at −1e300, to be filled while the interior is summed
      // (the ghost exchange before an action); without node sums, filled beforehand
      const Vector local_direction = d.local_part(direction, sums_mode == none);
      local.start_filling_copies(local_direction);
      if (convection)
        local.jacobian_action(d.local_part(state), local_direction, action);
      else
        local.linear_action(local_direction, action);  // its first loop reads the direction
      local.diagonal_blocks(d.local_part(state), blocks[sums_mode]);
      if (sums_mode == none) d.halo.sum_into_owners(action);  // the action's own sums, but not the gradient's
      differences[sums_mode] = d.largest_difference(action, expected.values);
    }
    // overlapped against after the loop: the same sums in another order
    const auto largest_gap = [&](const Vector& a, const Vector& b) {
      auto ha = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), a);
      auto hb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), b);
      double gap = 0.0, size = 0.0;
      for (std::size_t i = 0; i < ha.extent(0); ++i)
        gap = std::max(gap, std::fabs(ha(i) - hb(i))), size = std::max(size, std::fabs(hb(i)));
      return std::make_pair(d.world.max(gap), d.world.max(size));
    };
    const auto [block_gap, block_size] = largest_gap(blocks[overlapped], blocks[after_the_loop]);
    if (d.world.rank() == 0)
      std::printf("%s, %s, viscous reconstruction, %d ranks (%d of %zu elements on the boundary on rank 0): largest "
                  "difference from one rank %.2e overlapped, %.2e after the loop, %.2e without node sums (entries up "
                  "to %.3g); diagonal blocks overlapped against after the loop %.2e (entries up to %.3g)\n",
                  partition_name(mesh), convection ? "Navier-Stokes Jacobian action" : "Stokes action",
                  d.world.size(), d.partition.num_boundary_elements, d.partition.elements.size(),
                  differences[overlapped], differences[after_the_loop], differences[none], expected.largest, block_gap,
                  block_size);
    EXPECT_LT(differences[overlapped], 1e-13 * expected.largest);
    EXPECT_LT(differences[after_the_loop], 1e-13 * expected.largest);
    EXPECT_LT(block_gap, 1e-13 * block_size);
    if (d.world.size() > 1) EXPECT_GT(differences[none], 1e-6 * expected.largest);
    }
  }
}

TEST(RootGather, OneGlobalVectorForAnyRankCountAndBack) {
  // Gathered on rank 0, every rank's owned entries make the global vector bit for bit (the
  // file a checkpoint or an output step writes); scattered back, each rank gets its owned
  // entries, and update_copies completes them: a restart on another rank count.
  Distributed d;
  const HostVector global = random_vector(d.mesh.num_unknowns(), 21);
  const RootGather root(d.world, d.partition, 4);
  const std::vector<double> gathered = root.gather(d.local_part(global, false));
  if (root.is_root()) {  // EXPECT, not ASSERT: no rank may leave before the collectives below
    EXPECT_EQ(gathered.size(), static_cast<std::size_t>(d.mesh.num_unknowns()));
    int differing = 0;
    for (std::size_t i = 0; i < gathered.size(); ++i) differing += gathered[i] != global(i);
    EXPECT_EQ(differing, 0);
  } else {
    EXPECT_TRUE(gathered.empty());
  }
  Vector back("back", 4 * d.partition.num_local_nodes());
  root.scatter(gathered, back);
  d.halo.update_copies(back);
  EXPECT_EQ(d.largest_difference(back, global), 0.0);
}

TEST(FluidDistribution, ReplicatedGlobalVectorsAreTheSameOnEveryRankAndLocalizeBack) {
  // The whole vector from every rank's owned entries (copies left at −1e300: they must
  // not count), the same bit for bit as the global one on every rank; its nodes alone
  // (the cells' supports) leave every other entry as it was; localize() gives each rank
  // its part, copies included.
  for (const FluidMesh& mesh : partitioned_meshes()) {
    SCOPED_TRACE(partition_name(mesh));
    Distributed d(mesh);
    const FluidDistribution distribution(d.world, d.mesh);
    ASSERT_EQ(distribution.partition().global_node, d.partition.global_node);
    const HostVector global = random_vector(d.mesh.num_unknowns(), 23);
    const Vector local = d.local_part(global, false);
    Vector replicated("replicated", d.mesh.num_unknowns());
    distribution.replicate(local, replicated);
    auto all = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), replicated);
    int differing = 0;
    for (int i = 0; i < d.mesh.num_unknowns(); ++i) differing += all(i) != global(i);
    EXPECT_EQ(static_cast<int>(d.world.sum(static_cast<double>(differing))), 0);

    std::vector<int> some_nodes;
    for (int n = 1; n < d.mesh.num_dof_nodes; n += 3) some_nodes.push_back(n);
    Vector partial("partial", d.mesh.num_unknowns());
    Kokkos::deep_copy(partial, 7.0);
    distribution.replicate(local, partial, device_copy(some_nodes, "some_nodes"));
    auto part = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), partial);
    int wrong = 0;
    for (int n = 0; n < d.mesh.num_dof_nodes; ++n)
      for (int c = 0; c < 4; ++c)
        wrong += part(4 * n + c) != (n % 3 == 1 ? global(4 * n + c) : 7.0);
    EXPECT_EQ(static_cast<int>(d.world.sum(static_cast<double>(wrong))), 0);

    Vector back("back", 4 * d.partition.num_local_nodes());
    distribution.localize(replicated, back);
    EXPECT_EQ(d.largest_difference(back, global), 0.0);
    const double owned_norm = distribution.norm(back);
    double expected = 0.0;
    for (int i = 0; i < d.mesh.num_unknowns(); ++i) expected += global(i) * global(i);
    EXPECT_NEAR(owned_norm, std::sqrt(expected), 1e-12 * std::sqrt(expected));
  }
}

TEST(FluidDistribution, APointIsHeldByTheOwnerOfTheNearestNode) {
  // Every geometric node moved by up to 0.1 μm along each axis (a fifth of the smallest
  // spacing's half, so it stays nearest): rank_holding() names the owner of its dof node,
  // the same on every rank, through the periodic sides' images too; a point far outside
  // the fluid goes to rank 0.
  for (const FluidMesh& mesh : partitioned_meshes()) {
    SCOPED_TRACE(partition_name(mesh));
    Distributed d(mesh);
    const FluidDistribution distribution(d.world, d.mesh);
    std::vector<double> owner(d.mesh.num_dof_nodes, 0.0);
    for (int l = 0; l < d.partition.num_owned_nodes; ++l) owner[d.partition.global_node[l]] = d.world.rank();
    d.world.sum(owner.data(), static_cast<int>(owner.size()));
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), d.mesh.coordinates);
    std::mt19937 generator(5);
    std::uniform_real_distribution<double> shift(-0.1, 0.1);
    std::vector<std::array<double, 3>> points;
    for (int g = 0; g < d.mesh.num_nodes; ++g) points.push_back({x(g, 0) + shift(generator), x(g, 1) + shift(generator),
                                                                 x(g, 2) + shift(generator)});
    points.push_back({100.0, 100.0, 100.0});
    const std::vector<int> ranks = distribution.rank_holding(points);
    ASSERT_EQ(ranks.size(), points.size());
    int wrong = 0, held_here = 0;
    for (int g = 0; g < d.mesh.num_nodes; ++g) {
      wrong += ranks[g] != static_cast<int>(owner[d.mesh.dof_node_of_node[g]]);
      held_here += ranks[g] == d.world.rank();
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(ranks.back(), 0);
    // Every rank holds some points (it owns nodes), and each point is held once.
    EXPECT_GT(held_here, 0);
    EXPECT_EQ(d.world.sum(static_cast<long long>(held_here)), static_cast<long long>(d.mesh.num_nodes));
  }
}

TEST(FluidDistribution, TheNodesOfAnyRankAreTheUnionInOrderOnEveryRank) {
  // Rank r lists the dof nodes n with n mod (P + 1) = r, backwards, and node 5 (some twice):
  // every rank gets the union, ascending, each node once.
  Distributed d;
  const FluidDistribution distribution(d.world, d.mesh);
  const int ranks = d.world.size(), nodes = d.mesh.num_dof_nodes;
  std::vector<int> mine{5, 5};
  for (int n = nodes - 1; n >= 0; --n)
    if (n % (ranks + 1) == d.world.rank()) mine.push_back(n);
  const auto all = Kokkos::create_mirror_view_and_copy(
      Kokkos::HostSpace(), distribution.nodes_of_any_rank(device_copy(mine, "rouleau::test::mine")));
  std::vector<int> expected;
  for (int n = 0; n < nodes; ++n)
    if (n % (ranks + 1) < ranks || n == 5) expected.push_back(n);
  EXPECT_EQ(std::vector<int>(all.data(), all.data() + all.extent(0)), expected);
}

}  // namespace
}  // namespace rouleau
