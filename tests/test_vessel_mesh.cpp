// Gmsh meshes of vessel lumens (src/geometry/vessel_mesh): volume against the exact lumen
// volume under refinement, wall nodes on the exact wall, the boundary split into inlet,
// outlet and wall, determinism, the cache, and refused sizes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <filesystem>
#include <random>
#include <fstream>
#include <set>
#include <string>

#include "config/load_case.hpp"
#include "config/memory_estimate.hpp"
#include "fluid/fluid_matrix.hpp"
#include "geometry/vessel_mesh.hpp"
#include "run/simulation.hpp"
#include "solver/ilu0_preconditioner.hpp"
#include "temporary_folder.hpp"
#include "vessel_profiles.hpp"

namespace {

using rouleau::MeshPoint;
using rouleau::Triangle;
using rouleau::VesselMesh;
using rouleau::VesselMeshSizes;
using rouleau::VesselProfile;
using rouleau::testing::tube;

constexpr double pi = 3.14159265358979323846;

double mesh_volume(const VesselMesh& mesh) {
  double volume = 0.0;
  for (const auto& t : mesh.tetrahedra)
    volume += rouleau::signed_volume6(mesh.nodes[t[0]], mesh.nodes[t[1]], mesh.nodes[t[2]], mesh.nodes[t[3]]) / 6.0;
  return volume;
}

// Σ over triangles of the vector area (x1 − x0) × (x2 − x0) / 2.
std::array<double, 3> vector_area(const VesselMesh& mesh, const std::vector<Triangle>& triangles) {
  std::array<double, 3> sum{0, 0, 0};
  for (const auto& f : triangles) {
    const MeshPoint &a = mesh.nodes[f[0]], &b = mesh.nodes[f[1]], &c = mesh.nodes[f[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    sum[0] += 0.5 * (u[1] * v[2] - u[2] * v[1]);
    sum[1] += 0.5 * (u[2] * v[0] - u[0] * v[2]);
    sum[2] += 0.5 * (u[0] * v[1] - u[1] * v[0]);
  }
  return sum;
}

TEST(VesselMesh, TubeVolumeConvergesAtSecondOrderAndTheBoundaryCloses) {
  // Straight edges between nodes on the circle cut inside it: the volume deficit is
  // second order in h. The boundary of the lumen is closed: the vector areas of inlet,
  // outlet and wall sum to zero; inlet and outlet face −x and +x with areas → πR².
  const VesselProfile p = tube(3.0, 8.0);
  const double exact = rouleau::vessel_volume(p);
  std::vector<double> errors;
  const double sizes[2] = {1.0, 0.5};
  for (double h : sizes) {
    const VesselMesh mesh = rouleau::make_vessel_mesh(p, VesselMeshSizes{h, 0.0});
    errors.push_back(std::abs(mesh_volume(mesh) - exact) / exact);
    const auto inlet = vector_area(mesh, mesh.inlet), outlet = vector_area(mesh, mesh.outlet),
               wall = vector_area(mesh, mesh.wall);
    std::printf("tube R = 3, L = 8, h = %.2f: %zu nodes, %zu tetrahedra; volume error %.2e; inlet area %.4f "
                "(πR² = %.4f); closure %.1e\n",
                h, mesh.nodes.size(), mesh.tetrahedra.size(), errors.back(), -inlet[0], pi * 9.0,
                std::abs(inlet[0] + outlet[0] + wall[0]) + std::abs(inlet[1] + outlet[1] + wall[1]) +
                    std::abs(inlet[2] + outlet[2] + wall[2]));
    EXPECT_NEAR(-inlet[0], pi * 9.0, 0.025 * pi * 9.0);  // the polygon inside the circle
    EXPECT_NEAR(outlet[0], -inlet[0], 1e-9);
    EXPECT_NEAR(inlet[0] + outlet[0] + wall[0], 0.0, 1e-9);
    EXPECT_NEAR(inlet[1] + outlet[1] + wall[1], 0.0, 1e-9);
    EXPECT_NEAR(inlet[2] + outlet[2] + wall[2], 0.0, 1e-9);
    EXPECT_NEAR(inlet[1], 0.0, 1e-9);
    EXPECT_NEAR(inlet[2], 0.0, 1e-9);
  }
  const double order = std::log(errors[0] / errors[1]) / std::log(2.0);
  std::printf("tube volume error order %.2f\n", order);
  EXPECT_LT(errors[1], 5e-3);
  EXPECT_GT(order, 1.6);
}

TEST(VesselMesh, ContractionWallNodesLieOnTheProfileAndTheMeshIsGraded) {
  const VesselProfile p = rouleau::testing::small_contraction();
  const VesselMeshSizes sizes{0.8, 0.4};
  const VesselMesh mesh = rouleau::make_vessel_mesh(p, sizes);
  std::set<int> wall_nodes;
  for (const auto& f : mesh.wall) wall_nodes.insert(f.begin(), f.end());
  double worst = 0.0;
  for (int n : wall_nodes) {
    const MeshPoint& x = mesh.nodes[n];
    worst = std::max(worst, std::abs(std::hypot(x[1], x[2]) - rouleau::vessel_radius(p, x[0])));
  }
  const double volume_error = std::abs(mesh_volume(mesh) - rouleau::vessel_volume(p)) / rouleau::vessel_volume(p);
  // Throat: R_t/R = 1/2 of the feeders' sizes. Mean edge length of wall triangles in the
  // throat against those in the inlet feeder.
  double throat_edges = 0.0, feeder_edges = 0.0;
  int throat_count = 0, feeder_count = 0;
  for (const auto& f : mesh.wall) {
    const double x = (mesh.nodes[f[0]][0] + mesh.nodes[f[1]][0] + mesh.nodes[f[2]][0]) / 3.0;
    double edge = 0.0;
    for (int k = 0; k < 3; ++k) {
      const MeshPoint &a = mesh.nodes[f[k]], &b = mesh.nodes[f[(k + 1) % 3]];
      edge += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) / 3.0;
    }
    if (x > 8.5 && x < 10.5) throat_edges += edge, ++throat_count;
    if (x > 0.5 && x < 3.5) feeder_edges += edge, ++feeder_count;
  }
  throat_edges /= throat_count;
  feeder_edges /= feeder_count;
  std::printf("contraction 3 → 1.5 μm: %zu nodes, %zu tetrahedra; wall nodes off the profile by ≤ %.1e μm; volume "
              "error %.2e; mean wall edge %.3f μm in the throat, %.3f μm in the feeder\n",
              mesh.nodes.size(), mesh.tetrahedra.size(), worst, volume_error, throat_edges, feeder_edges);
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(volume_error, 1e-2);
  EXPECT_NEAR(throat_edges / feeder_edges, 0.5, 0.15);
}

TEST(VesselMesh, IsTheSameEveryRunAndIsCached) {
  const VesselProfile p = tube(2.0, 4.0);
  const VesselMeshSizes sizes{0.8, 0.0};
  const VesselMesh first = rouleau::make_vessel_mesh(p, sizes), second = rouleau::make_vessel_mesh(p, sizes);
  EXPECT_EQ(first.nodes, second.nodes);
  EXPECT_EQ(first.tetrahedra, second.tetrahedra);
  EXPECT_EQ(first.wall, second.wall);

  const std::string dir = ::testing::TempDir() + "rouleau_vessel_cache";
  std::filesystem::remove_all(dir);
  const VesselMesh stored = rouleau::vessel_mesh(p, sizes, dir);
  const std::string file = dir + "/vesselmesh-" + stored.hash + ".txt";
  ASSERT_TRUE(std::filesystem::exists(file));
  const VesselMesh read = rouleau::vessel_mesh(p, sizes, dir);
  EXPECT_EQ(read.nodes, first.nodes);
  EXPECT_EQ(read.tetrahedra, first.tetrahedra);
  EXPECT_EQ(read.inlet, first.inlet);
  EXPECT_EQ(read.outlet, first.outlet);
  // A truncated cache file is remade, not trusted, and stored whole again.
  const auto whole = std::filesystem::file_size(file);
  std::filesystem::resize_file(file, whole / 2);
  const VesselMesh remade = rouleau::vessel_mesh(p, sizes, dir);
  EXPECT_EQ(remade.tetrahedra, first.tetrahedra);
  EXPECT_EQ(std::filesystem::file_size(file), whole);
  std::filesystem::remove_all(dir);
}

TEST(VesselMesh, RenumberingNarrowsTheBandAndKeepsTheMesh) {
  // The tube's nodes shuffled at random, then renumbered by reverse Cuthill–McKee: the
  // largest index difference along an edge (the band the element loops gather from) must
  // shrink by far, and every tetrahedron keep its corners' positions and its volume.
  // A tube 8 diameters long (R = 2, L = 32 μm): a band of a few cross-sections against
  // the whole mesh.
  const VesselMesh vessel = rouleau::make_vessel_mesh(tube(2.0, 32.0), VesselMeshSizes{0.5, 0.0});
  std::vector<MeshPoint> nodes = vessel.nodes;
  std::vector<rouleau::Tetrahedron> tetrahedra = vessel.tetrahedra;
  std::vector<int> shuffle(nodes.size());
  for (std::size_t i = 0; i < shuffle.size(); ++i) shuffle[i] = static_cast<int>(i);
  std::mt19937 rng(5);
  std::shuffle(shuffle.begin(), shuffle.end(), rng);
  std::vector<MeshPoint> shuffled(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) shuffled[shuffle[i]] = nodes[i];
  for (auto& t : tetrahedra)
    for (int& v : t) v = shuffle[v];
  const auto bandwidth = [](const std::vector<rouleau::Tetrahedron>& elements) {
    int band = 0;
    for (const auto& t : elements)
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) band = std::max(band, std::abs(t[i] - t[j]));
    return band;
  };
  const int before = bandwidth(tetrahedra);
  const std::vector<rouleau::Tetrahedron> shuffled_tetrahedra = tetrahedra;
  rouleau::renumber_nodes_for_locality(shuffled, tetrahedra);
  const int after = bandwidth(tetrahedra);
  std::printf("renumbering %zu nodes: bandwidth %d shuffled, %d after\n", shuffled.size(), before, after);
  EXPECT_LT(after * 10, before);
  for (std::size_t e = 0; e < tetrahedra.size(); ++e)
    for (int v = 0; v < 4; ++v)
      EXPECT_EQ(shuffled[tetrahedra[e][v]], vessel.nodes[vessel.tetrahedra[e][v]]);
}

// Mean edge length of the wall triangles whose centroid lies in [from, to] along the axis.
double mean_wall_edge(const VesselMesh& mesh, double from, double to) {
  double sum = 0.0;
  int count = 0;
  for (const auto& f : mesh.wall) {
    const double x = (mesh.nodes[f[0]][0] + mesh.nodes[f[1]][0] + mesh.nodes[f[2]][0]) / 3.0;
    if (x < from || x > to) continue;
    for (int k = 0; k < 3; ++k) {
      const MeshPoint &a = mesh.nodes[f[k]], &b = mesh.nodes[f[(k + 1) % 3]];
      sum += std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) / 3.0;
    }
    ++count;
  }
  return sum / count;
}

TEST(VesselMesh, ARefinedStretchHasTheScaledSizeAndTheRestKeepsItsOwn) {
  // A tube of radius 3 μm, 12 μm long, h = 0.8, h_w = 0.4 μm, the stretch 5–8 μm refined by
  // s_r = 0.5 (blending back over 2h = 1.6 μm): the wall's edges inside it half those at
  // the inlet, which lies more than 1.6 μm away; the volume still right.
  const VesselProfile p = tube(3.0, 12.0);
  VesselMeshSizes sizes{0.8, 0.4};
  sizes.refined_scale = 0.5;
  sizes.refined_from = 5.0;
  sizes.refined_to = 8.0;
  const VesselMesh refined = rouleau::make_vessel_mesh(p, sizes);
  const VesselMesh plain = rouleau::make_vessel_mesh(p, VesselMeshSizes{0.8, 0.4});
  const double inside = mean_wall_edge(refined, 5.3, 7.7), outside = mean_wall_edge(refined, 0.3, 3.0);
  const double plain_outside = mean_wall_edge(plain, 0.3, 3.0);
  const double volume_error = std::abs(mesh_volume(refined) - rouleau::vessel_volume(p)) / rouleau::vessel_volume(p);
  std::printf("refined stretch ×0.5: %zu tetrahedra (%zu without); mean wall edge %.3f μm inside, %.3f μm at the "
              "inlet (%.3f without); volume error %.2e; smallest size %.3f μm\n",
              refined.tetrahedra.size(), plain.tetrahedra.size(), inside, outside, plain_outside, volume_error,
              rouleau::smallest_vessel_element_size(p, sizes));
  EXPECT_NEAR(inside / outside, 0.5, 0.1);
  EXPECT_NEAR(outside / plain_outside, 1.0, 0.1);
  EXPECT_LT(volume_error, 1e-2);
  EXPECT_DOUBLE_EQ(rouleau::smallest_vessel_element_size(p, sizes), 0.2);
  EXPECT_NE(refined.hash, plain.hash);
}

TEST(VesselMesh, BadSizesAreRefusedWithTheKey) {
  const VesselProfile p = tube(3.0, 8.0);
  auto problem = rouleau::vessel_mesh_sizes_problem(p, VesselMeshSizes{0.5, 0.8});
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->key, "wall_element_size_um");
  problem = rouleau::vessel_mesh_sizes_problem(p, VesselMeshSizes{-1.0, 0.0});
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->key, "element_size_um");
  problem = rouleau::vessel_mesh_sizes_problem(p, VesselMeshSizes{0.01, 0.0});
  ASSERT_TRUE(problem);
  EXPECT_NE(problem->reason.find("tetrahedra expected"), std::string::npos) << problem->reason;
  EXPECT_FALSE(rouleau::vessel_mesh_sizes_problem(p, VesselMeshSizes{0.5, 0.25}));
  VesselMeshSizes refined{0.5, 0.25};
  refined.refined_scale = 0.0;
  EXPECT_EQ(rouleau::vessel_mesh_sizes_problem(p, refined)->key, "refined_element_scale");
  refined.refined_scale = 0.5;
  refined.refined_from = 4.0;
  refined.refined_to = 3.0;
  EXPECT_EQ(rouleau::vessel_mesh_sizes_problem(p, refined)->key, "refined_to_um");
  refined.refined_from = 9.0;
  refined.refined_to = 12.0;
  EXPECT_EQ(rouleau::vessel_mesh_sizes_problem(p, refined)->key, "refined_to_um");
  refined.refined_from = 2.0;
  refined.refined_to = 5.0;
  EXPECT_FALSE(rouleau::vessel_mesh_sizes_problem(p, refined));
  try {
    VesselProfile wide = tube(3.0, 8.0);
    wide.throat_radius = 4.0;
    rouleau::make_vessel_mesh(wide, VesselMeshSizes{1.0, 0.0});
    ADD_FAILURE() << "a throat wider than the inlet was meshed";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("vessel.throat_radius_um"), std::string::npos) << error.what();
  }
}

TEST(VesselMesh, MemoryEstimateCountsTheTetrahedraBeforeGmshMeshesThem) {
  // The contraction's lumen at two element sizes: the nodes, tetrahedra, Jacobian blocks
  // and ILU(0)'s widest level, estimated from the size field before meshing, against the
  // mesh Gmsh makes and the graph and factorization the solver builds on it.
  const std::string cache = rouleau::testing::fresh_temporary_folder("memory_estimate_vessel_cache").string();
  for (const std::string sizes : {"3.0,1.5", "2.0,1.0"}) {
    SCOPED_TRACE(sizes);
    const std::string core = sizes.substr(0, sizes.find(',')), wall = sizes.substr(sizes.find(',') + 1);
    const rouleau::CaseConfig config = rouleau::load_case(
        std::string(ROULEAU_SOURCE_DIR) + "/cases/contraction/case.toml",
        {"cells=[]", "interaction.enabled=false", "vessel.element_size_um=" + core, "vessel.wall_element_size_um=" + wall});
    const rouleau::MemoryEstimate estimate = rouleau::estimate_memory(config, 2);
    const rouleau::FluidMesh mesh = rouleau::make_case_mesh(config, cache);
    const rouleau::BlockMatrixGraph graph = rouleau::build_fluid_matrix_graph(mesh);
    const rouleau::Ilu0Preconditioner ilu(graph.row_map, graph.entries);
    const double blocks = static_cast<double>(graph.node_neighbors.extent(0)), widest = ilu.widest_level();
    std::printf("contraction %s um: %d nodes (estimate %lld), %d tetrahedra (%lld), %.0f blocks (%.0f), widest ILU(0) "
                "level %.0f rows (%.0f)\n",
                sizes.c_str(), mesh.num_dof_nodes, estimate.fluid_nodes, mesh.num_elements, estimate.fluid_elements,
                blocks, estimate.jacobian_blocks, widest, estimate.widest_ilu_level);
    EXPECT_NEAR(static_cast<double>(estimate.fluid_nodes), mesh.num_dof_nodes, 0.3 * mesh.num_dof_nodes);
    EXPECT_NEAR(static_cast<double>(estimate.fluid_elements), mesh.num_elements, 0.3 * mesh.num_elements);
    EXPECT_NEAR(estimate.jacobian_blocks, blocks, 0.3 * blocks);
    EXPECT_NEAR(estimate.widest_ilu_level, widest, 0.5 * widest);
  }
}

}  // namespace
