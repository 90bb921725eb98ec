// The fluid mesh split across ranks, checked in one process by building every
// rank's partition: the block grid cuts the fewest faces; every element, every dof node
// and every boundary face has exactly one owner; the shared-node lists of two ranks match entry for entry; and the
// rank-local operators, their element sums added at the owners, give the whole mesh's
// Stokes and Navier–Stokes actions to round-off (the MPI run of the same: mpi_halo.cpp);
// for the box's block partition and for a METIS partition of its tetrahedra.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <Kokkos_Random.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <vector>

#include "distributed/local_mesh.hpp"
#include "fluid/fluid_operator.hpp"
#include "mesh/fluid_mesh.hpp"
#include "parallel/element_partition.hpp"
#include "partitioned_meshes.hpp"

namespace rouleau {
namespace {

using testing::partition_name;
using testing::partitioned_meshes;
using testing::shear_box;

long long faces_cut(const std::array<int, 3>& n, const std::array<int, 3>& p) {
  return (p[0] - 1) * 1LL * n[1] * n[2] + (p[1] - 1) * 1LL * n[0] * n[2] + (p[2] - 1) * 1LL * n[0] * n[1];
}

TEST(BlockGrid, CutsTheFewestFaces) {
  // Against every factorization p_x p_y p_z = ranks that fits the box.
  const std::vector<std::array<int, 3>> boxes{{8, 4, 4}, {40, 20, 20}, {3, 17, 5}, {64, 64, 64}};
  for (const std::array<int, 3>& n : boxes)
    for (int ranks = 1; ranks <= 24; ++ranks) {
      long long best = -1;
      for (int px = 1; px <= ranks; ++px)
        for (int py = 1; py <= ranks; ++py) {
          if (ranks % (px * py) != 0) continue;
          const int pz = ranks / (px * py);
          if (px > n[0] || py > n[1] || pz > n[2]) continue;
          const long long cut = faces_cut(n, {px, py, pz});
          if (best < 0 || cut < best) best = cut;
        }
      if (best < 0) {
        EXPECT_THROW(block_grid(n, ranks), std::invalid_argument);
        continue;
      }
      const std::array<int, 3> p = block_grid(n, ranks);
      EXPECT_EQ(p[0] * p[1] * p[2], ranks);
      EXPECT_EQ(faces_cut(n, p), best) << n[0] << "x" << n[1] << "x" << n[2] << " on " << ranks;
    }
  EXPECT_EQ(block_grid({40, 20, 20}, 2), (std::array<int, 3>{2, 1, 1}));
  EXPECT_EQ(block_grid({40, 20, 20}, 8), (std::array<int, 3>{4, 2, 1}));  // ties with 2x2x2: x first
}

TEST(BlockElementOwners, EvenBlocks) {
  const std::array<int, 3> n{10, 7, 3};
  for (const int ranks : {1, 2, 3, 5, 6, 7}) {
    const std::vector<int> owner = block_element_owners(n, ranks);
    std::vector<int> count(ranks, 0);
    for (const int r : owner) ++count[r];
    const auto [fewest, most] = std::minmax_element(count.begin(), count.end());
    const std::array<int, 3> p = block_grid(n, ranks);
    // blocks differ by at most one element plane per direction
    int slack = 1;
    for (int d = 0; d < 3; ++d) slack *= n[d] / p[d] + 1;
    EXPECT_GT(*fewest, 0);
    EXPECT_LE(*most, slack);
  }
}

std::vector<ElementPartition> all_partitions(const FluidMesh& mesh, int ranks) {
  std::vector<ElementPartition> partitions;
  for (int r = 0; r < ranks; ++r) partitions.push_back(partition_fluid_mesh(mesh, r, ranks));
  return partitions;
}

TEST(ElementPartition, OwnsEveryElementAndNodeOnceAndSharesConsistently) {
  if (!has_graph_partitioner()) std::printf("no METIS in this build: the box alone\n");
  for (const FluidMesh& mesh : partitioned_meshes()) {
  auto connectivity = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_dof_nodes);
  for (const int ranks : {1, 2, 3, 4, 6, 8}) {
    const std::vector<ElementPartition> parts = all_partitions(mesh, ranks);
    std::vector<int> element_owners(mesh.num_elements, 0), node_owners(mesh.num_dof_nodes, 0);
    for (const ElementPartition& p : parts) {
      for (const int e : p.elements) ++element_owners[e];
      // the local nodes are exactly the nodes of the rank's elements
      std::vector<int> touched;
      for (const int e : p.elements)
        for (int a = 0; a < mesh.nodes_per_element; ++a) touched.push_back(connectivity(e, a));
      std::sort(touched.begin(), touched.end());
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
      std::vector<int> local = p.global_node;
      std::sort(local.begin(), local.end());
      EXPECT_EQ(local, touched);
      for (int l = 0; l < p.num_local_nodes(); ++l) {
        EXPECT_EQ(p.node_owner[l] == p.rank, l < p.num_owned_nodes);
        if (l < p.num_owned_nodes) ++node_owners[p.global_node[l]];
        if (l > 0 && l != p.num_owned_nodes) EXPECT_LT(p.global_node[l - 1], p.global_node[l]);
      }
      // boundary elements first: they and only they touch a node another rank holds
      // (checked against every other rank's nodes), each group in ascending global id
      std::vector<char> held_elsewhere(mesh.num_dof_nodes, 0);
      for (const ElementPartition& other : parts)
        if (other.rank != p.rank)
          for (const int g : other.global_node) held_elsewhere[g] = 1;
      ASSERT_LE(p.num_boundary_elements, static_cast<int>(p.elements.size()));
      if (ranks == 1) EXPECT_EQ(p.num_boundary_elements, 0);
      for (std::size_t i = 0; i < p.elements.size(); ++i) {
        bool touches = false;
        for (int a = 0; a < mesh.nodes_per_element; ++a) touches = touches || held_elsewhere[connectivity(p.elements[i], a)];
        EXPECT_EQ(touches, static_cast<int>(i) < p.num_boundary_elements) << "element " << p.elements[i];
        if (i > 0 && static_cast<int>(i) != p.num_boundary_elements) EXPECT_LT(p.elements[i - 1], p.elements[i]);
      }
      // what r sends s is what s expects from r, node for node
      for (const NeighborExchange& link : p.neighbors) {
        const ElementPartition& other = parts[link.rank];
        const auto back = std::find_if(other.neighbors.begin(), other.neighbors.end(),
                                       [&](const NeighborExchange& n) { return n.rank == p.rank; });
        ASSERT_NE(back, other.neighbors.end());
        ASSERT_EQ(link.owned_shared.size(), back->copies.size());
        ASSERT_EQ(link.copies.size(), back->owned_shared.size());
        for (std::size_t i = 0; i < link.owned_shared.size(); ++i)
          EXPECT_EQ(p.global_node[link.owned_shared[i]], other.global_node[back->copies[i]]);
        for (std::size_t i = 0; i < link.copies.size(); ++i)
          EXPECT_EQ(p.global_node[link.copies[i]], other.global_node[back->owned_shared[i]]);
      }
    }
    for (const int c : element_owners) ASSERT_EQ(c, 1);
    for (const int c : node_owners) ASSERT_EQ(c, 1);
    // every boundary face on exactly one rank's mesh (a traction or a flux counted once)
    for (std::size_t side = 0; side < mesh.boundaries.size(); ++side) {
      std::size_t faces = 0;
      for (const ElementPartition& p : parts) faces += make_local_mesh(mesh, p).boundaries[side].faces.size();
      EXPECT_EQ(faces, mesh.boundaries[side].faces.size()) << mesh.boundaries[side].name << ", " << ranks << " ranks";
    }
    // balanced: blocks as even as whole planes of elements allow (at most Π ⌈n_d/p_d⌉);
    // METIS within its 3 % (+1 element)
    std::size_t fewest = mesh.num_elements, most = 0;
    for (const ElementPartition& p : parts) fewest = std::min(fewest, p.elements.size()), most = std::max(most, p.elements.size());
    std::printf("%s, %d ranks: %zu to %zu elements per rank, %d elements\n", partition_name(mesh), ranks, fewest, most,
                mesh.num_elements);
    if (mesh.element_type == FluidElementType::hexahedron8) {
      const std::array<int, 3> p = block_grid(mesh.structured_elements, ranks);
      std::size_t largest_block = 1;
      for (int d = 0; d < 3; ++d) largest_block *= (mesh.structured_elements[d] + p[d] - 1) / p[d];
      EXPECT_LE(most, largest_block);
    } else {
      EXPECT_LE(static_cast<double>(most), 1.03 * mesh.num_elements / ranks + 1.0);
    }
    if (ranks == 2 && mesh.element_type == FluidElementType::hexahedron8) {
      // periodic in x and split in x: the two halves meet at x = 6 and across the periodic
      // plane x = 0 ≡ 12, two planes of 5 × 6 dof nodes
      EXPECT_EQ(parts[0].neighbors.size(), 1u);
      EXPECT_EQ(parts[0].neighbors[0].owned_shared.size() + parts[0].neighbors[0].copies.size(), 60u);
    }
  }
  }
}

// The global vector → one rank's local vector (4 entries per dof node).
Vector local_part(const Kokkos::View<double*, Kokkos::HostSpace>& global, const ElementPartition& p) {
  Vector local("local", 4 * p.num_local_nodes());
  auto h = Kokkos::create_mirror_view(local);
  for (int l = 0; l < p.num_local_nodes(); ++l)
    for (int c = 0; c < 4; ++c) h(4 * l + c) = global(4 * p.global_node[l] + c);
  Kokkos::deep_copy(local, h);
  return local;
}

TEST(ElementPartition, RankLocalOperatorsSumToTheGlobalOperator) {
  // Every rank's FluidOperator on its local mesh (element path); its element sums added into
  // a global vector at the global ids (what NodeHalo::sum_into_owners does across ranks)
  // against the global operator, for the Stokes action and the Navier–Stokes Jacobian
  // action, 1, 2, 3 and 4 ranks. The sums differ only in order: relative difference < 1e-13.
  for (const FluidMesh& mesh : partitioned_meshes()) {
  FluidCoefficients c;
  c.reynolds = 2.0;
  c.mass_coefficient = 1.5 / 0.1;
  c.inverse_dt = 1.0 / 0.1;
  const int n = mesh.num_unknowns();
  Vector state("state", n), direction("direction", n);
  Kokkos::Random_XorShift64_Pool<> pool(2024);
  Kokkos::fill_random(state, pool, -1.0, 1.0);
  Kokkos::fill_random(direction, pool, -1.0, 1.0);
  const auto state_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), state);
  const auto direction_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), direction);
  for (const int convection : {0, 1}) {
    c.convection = convection;
    FluidOperator global(mesh, 1.0);
    global.allow_stencil(false);
    global.set_coefficients(c);
    Vector expected("expected", n);
    if (convection)
      global.jacobian_action(state, direction, expected);
    else
      global.linear_action(direction, expected);
    const auto expected_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), expected);
    for (const int ranks : {1, 2, 3, 4}) {
      std::vector<double> summed(n, 0.0);
      for (const ElementPartition& p : all_partitions(mesh, ranks)) {
        FluidOperator local(make_local_mesh(mesh, p), 1.0);
        local.set_coefficients(c);
        EXPECT_FALSE(local.uses_stencil());
        Vector action("action", 4 * p.num_local_nodes());
        if (convection)
          local.jacobian_action(local_part(state_host, p), local_part(direction_host, p), action);
        else
          local.linear_action(local_part(direction_host, p), action);
        const auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), action);
        for (int l = 0; l < p.num_local_nodes(); ++l)
          for (int k = 0; k < 4; ++k) summed[4 * p.global_node[l] + k] += h(4 * l + k);
      }
      double difference = 0.0, norm = 0.0;
      for (int i = 0; i < n; ++i) {
        difference += std::pow(summed[i] - expected_host(i), 2);
        norm += expected_host(i) * expected_host(i);
      }
      std::printf("%s, %s on %d ranks: rank-local element sums vs the global operator, relative difference %.2e\n",
                  partition_name(mesh), convection ? "Navier-Stokes Jacobian action" : "Stokes action", ranks,
                  std::sqrt(difference / norm));
      EXPECT_LT(std::sqrt(difference / norm), 1e-13);
    }
  }
  }
}

}  // namespace
}  // namespace rouleau
