// The Morse cell–cell surface interaction (paper eqs. 3, 4, 11): the law, the neighbour
// list and the pair kernel against a brute-force double loop, Newton's third law, the
// energy gradient, the exact stiffness (the pairs' Hessian blocks), the plate–plate
// integral, the skin, and two rigid cells settling at the Morse minimum.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <vector>

#include "cells/cell_population.hpp"
#include "cells/cells_from_case.hpp"
#include "cells/surface_interaction.hpp"
#include "config/cell_kinds.hpp"
#include "kernels/morse.hpp"
#include "kernels/morse_pairs.hpp"
#include "test_helpers.hpp"
#include "tet_box_mesh.hpp"

namespace rouleau {
namespace {

// β = 4/μm > ln 2 / r0 (DESIGN: plates then balance at a positive gap).
MorsePotential test_potential(double well_depth = 1.0) { return {well_depth, 4.0, 0.25, 3.0}; }

template <class View>
auto host_copy(const View& v) {
  auto copy = Kokkos::create_mirror(Kokkos::HostSpace(), v);
  Kokkos::deep_copy(copy, v);
  return copy;
}

TEST(MorsePotential, Identities) {
  // Eqs. (3)-(4) as printed: φ(r0) = −De, f(r0) = 0, the strongest attraction −f = βDe/2
  // at r0 + ln 2/β. The shifted law: f_s = f − f(r_c) and φ_s both vanish at r_c, and
  // f_s = −φ_s' everywhere below r_c.
  const MorsePotential m{2.5, 4.0, 0.25, 3.0};
  EXPECT_NEAR(m.unshifted_energy(0.25), -2.5, 1e-15);
  EXPECT_NEAR(m.unshifted_force(0.25), 0.0, 1e-15);
  const double r_star = 0.25 + std::log(2.0) / 4.0;
  EXPECT_NEAR(m.unshifted_force(r_star), -4.0 * 2.5 / 2.0, 1e-14);
  EXPECT_NEAR((m.unshifted_force(r_star + 1e-5) - m.unshifted_force(r_star - 1e-5)) / 2e-5, 0.0, 1e-6);
  EXPECT_EQ(m.force(3.0), 0.0);
  EXPECT_NEAR(m.energy(3.0), 0.0, 1e-18);
  // The shift: f(r_c) = 2βDe (e^{−2β(r_c−r0)} − e^{−β(r_c−r0)}), about −1.3e-4 De here.
  const double tail = std::exp(-4.0 * 2.75);
  EXPECT_NEAR(m.cutoff_force, 2.0 * 4.0 * 2.5 * (tail * tail - tail), 1e-18);
  EXPECT_NEAR(m.force(0.7) - m.unshifted_force(0.7), -m.cutoff_force, 1e-15);
  double worst = 0.0;
  for (double r = 0.05; r < 3.0; r += 0.137) {
    const double derivative = (m.energy(r + 1e-6) - m.energy(r - 1e-6)) / 2e-6;
    worst = std::max(worst, std::fabs(m.force(r) + derivative) / (std::fabs(m.force(r)) + 1e-3));
    double energy = 0.0;
    EXPECT_EQ(m.force_and_energy(r, energy), m.force(r));
    EXPECT_EQ(energy, m.energy(r));
  }
  EXPECT_LT(worst, 1e-7);
}

TEST(MorsePotential, CaseLawsMixTheKindsFactorsAndTakeThePairEntries) {
  // normal (factor 1), sickle (5), capsule (1); strength 2; capsule–capsule set apart.
  CaseConfig config;
  config.cell_kinds = builtin_cell_kinds();
  config.interaction.strength = 2.0;
  MorsePairConfig pair;
  pair.kind_a = pair.kind_b = "capsule";
  pair.morse = {7.0, 5.0, 0.3, 2.0};
  config.interaction.pairs.push_back(pair);
  const std::vector<MorsePotential> laws = case_morse_potentials(config);
  const double de = config.interaction.morse.well_depth;
  ASSERT_EQ(laws.size(), 9u);
  EXPECT_DOUBLE_EQ(laws[0 * 3 + 0].well_depth, 2.0 * de);                  // normal–normal
  EXPECT_DOUBLE_EQ(laws[1 * 3 + 1].well_depth, 2.0 * 5.0 * de);            // sickle–sickle
  EXPECT_DOUBLE_EQ(laws[0 * 3 + 1].well_depth, 2.0 * std::sqrt(5.0) * de);  // normal–sickle
  EXPECT_DOUBLE_EQ(laws[1 * 3 + 0].well_depth, laws[0 * 3 + 1].well_depth);
  EXPECT_DOUBLE_EQ(laws[2 * 3 + 2].well_depth, 14.0);                       // the pair entry, × strength
  EXPECT_DOUBLE_EQ(laws[2 * 3 + 2].beta, 5.0);
  EXPECT_DOUBLE_EQ(laws[2 * 3 + 2].cutoff, 2.0);
}

TEST(MorsePotential, AutomaticQuadratureFollowsTheNodeSpacing) {
  // Nodes 0.5 μm apart with 1/β = 0.25 μm: Gauss points; 0.125 μm apart: the nodes.
  const std::vector<MorsePotential> laws{test_potential()};
  const std::map<std::string, CellMesh> coarse{{"a", testing::tetrahedral_box(4, 2.0)}};
  const std::map<std::string, CellMesh> fine{{"a", testing::tetrahedral_box(16, 2.0)}};
  EXPECT_EQ(surface_quadrature_for(InteractionQuadrature::automatic, coarse, laws), SurfaceQuadrature::gauss3);
  EXPECT_EQ(surface_quadrature_for(InteractionQuadrature::automatic, fine, laws), SurfaceQuadrature::nodes);
  EXPECT_EQ(surface_quadrature_for(InteractionQuadrature::gauss6, fine, laws), SurfaceQuadrature::gauss6);
  EXPECT_EQ(surface_quadrature_for(InteractionQuadrature::nodes, coarse, laws), SurfaceQuadrature::nodes);
}

// Cells made of tetrahedral cubes, placed and randomly turned and jittered.
struct Scene {
  std::vector<CellMesh> meshes;
  std::unique_ptr<CellPopulation> cells;

  Scene(const std::vector<Eigen::Vector3d>& centers, std::uint32_t seed, int n = 4, double size = 2.0) {
    meshes.assign(centers.size(), testing::tetrahedral_box(n, size));
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> angle(-0.3, 0.3);
    std::vector<PlacedCell> placed(centers.size());
    for (std::size_t c = 0; c < centers.size(); ++c) {
      const Eigen::Matrix3d r = (Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitX()) *
                                 Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitY()))
                                    .toRotationMatrix();
      placed[c].mesh = &meshes[c];
      for (int i = 0; i < 3; ++i) {
        placed[c].center[i] = centers[c][i];
        for (int j = 0; j < 3; ++j) placed[c].rotation[i][j] = r(i, j);
      }
    }
    cells = std::make_unique<CellPopulation>(placed);
  }
  void jitter(std::uint32_t seed, double amplitude) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    auto x = host_copy(cells->positions());
    for (std::size_t n = 0; n < x.extent(0); ++n)
      for (int i = 0; i < 3; ++i) x(n, i) += u(rng);
    cells->set_positions(x);
  }
};

SurfaceInteraction make_interaction(const CellPopulation& cells, const MorsePotential& potential, double skin,
                                    bool half_list, SurfaceQuadrature quadrature = SurfaceQuadrature::nodes) {
  return SurfaceInteraction(cells, std::vector<int>(cells.num_cells(), 0), 1, {potential}, skin, half_list,
                            quadrature);
}

// The interaction forces on the nodes (host, node-major).
std::vector<Eigen::Vector3d> node_forces(const CellPopulation& cells, const SurfaceInteraction& interaction) {
  CellPopulation::NodeVectors forces("node_forces", cells.num_nodes());
  interaction.copy_forces_to_nodes(forces);
  const auto f = host_copy(forces);
  std::vector<Eigen::Vector3d> result(cells.num_nodes());
  for (int n = 0; n < cells.num_nodes(); ++n) result[n] = Eigen::Vector3d(f(n, 0), f(n, 1), f(n, 2));
  return result;
}

// The brute-force reference: every pair of surface points of different cells.
struct Reference {
  std::vector<Eigen::Vector3d> forces;
  double energy = 0.0;
};
Reference brute_force(const CellPopulation& cells, const SurfaceInteraction& interaction,
                      const MorsePotential& potential) {
  const auto x = host_copy(interaction.point_positions());
  const auto weight = host_copy(interaction.point_weight());
  const auto cell = host_copy(interaction.point_cell());
  Reference result;
  const int n = interaction.num_points();
  result.forces.assign(n, Eigen::Vector3d::Zero());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (i == j || cell(i) == cell(j)) continue;
      const Eigen::Vector3d d(x(i, 0) - x(j, 0), x(i, 1) - x(j, 1), x(i, 2) - x(j, 2));
      const double r = d.norm();
      if (r >= potential.cutoff) continue;
      result.forces[i] += weight(i) * weight(j) * potential.force(r) / r * d;
      if (j > i) result.energy += weight(i) * weight(j) * potential.energy(r);
    }
  return result;
}

double force_difference(const SurfaceInteraction& interaction, const Reference& reference) {
  const auto f = host_copy(interaction.forces());
  double error = 0.0, norm = 0.0;
  for (int i = 0; i < interaction.num_points(); ++i) {
    error += (Eigen::Vector3d(f(i, 0), f(i, 1), f(i, 2)) - reference.forces[i]).squaredNorm();
    norm += reference.forces[i].squaredNorm();
  }
  return std::sqrt(error / norm);
}

TEST(InterleavedRows, VisitEveryRowOnce) {
  // row_of over extent() indices is a permutation of the rows (the padding indices map past
  // the end), each block's rows come as one run of consecutive indices, and a contiguous
  // quarter of the indices meets rows all over the range.
  for (const int rows : {1, 5, 63, 64, 65, 1000, 4097, 20000})
    for (const int stride : {1, 2, 7, 64})
      for (const int block : {1, 3, 64}) {
        const InterleavedRows order{rows, stride, block};
        const int extent = order.extent();
        std::vector<int> seen(rows, 0);
        for (int i = 0; i < extent; ++i) {
          const int row = order.row_of(i);
          ASSERT_GE(row, 0);
          if (row < rows) ++seen[row];
          if (i % block != 0) ASSERT_EQ(row, order.row_of(i - 1) + 1);
        }
        for (int row = 0; row < rows; ++row)
          ASSERT_EQ(seen[row], 1) << rows << " rows, stride " << stride << ", block " << block;
        if (stride == 64 && rows >= 64 * block * 16) {
          int lowest = rows, highest = -1;
          for (int i = 0; i < extent / 4; ++i) {
            const int row = order.row_of(i);
            if (row < rows) lowest = std::min(lowest, row), highest = std::max(highest, row);
          }
          EXPECT_LT(lowest, rows / 20);
          EXPECT_GT(highest, rows - rows / 20);
        }
      }
}

TEST(SurfaceInteraction, MatchesABruteForceDoubleLoop) {
  // Four cubes 0.4–1.5 μm apart, turned and jittered, plus one far away; full and half lists.
  Scene scene({{0, 0, 0}, {2.6, 0.2, 0}, {0.3, 3.4, 0.5}, {2.5, 2.6, -0.2}, {30, 0, 0}}, 3);
  scene.jitter(5, 0.1);
  const MorsePotential potential = test_potential();
  for (const auto quadrature : {SurfaceQuadrature::nodes, SurfaceQuadrature::gauss3})
  for (const bool half : {false, true}) {
    SurfaceInteraction interaction = make_interaction(*scene.cells, potential, 0.3, half, quadrature);
    const double energy = interaction.compute_forces_and_energy();
    const Reference reference = brute_force(*scene.cells, interaction, potential);
    const double difference = force_difference(interaction, reference);
    std::cout << "  " << (quadrature == SurfaceQuadrature::nodes ? "nodal quadrature, " : "3 Gauss points per triangle, ")
              << (half ? "half" : "full") << " list: " << interaction.num_points() << " surface points, "
              << interaction.num_list_entries() << " list entries, " << interaction.active_cell_count()
              << " of 5 cells active; forces vs brute force " << difference << ", energy "
              << std::fabs(energy / reference.energy - 1.0) << " (relative)\n";
    EXPECT_LT(difference, 1e-13);
    EXPECT_NEAR(energy / reference.energy, 1.0, 1e-13);
    EXPECT_EQ(interaction.active_cell_count(), 4);  // the far cube does no pair work
  }
}

TEST(SurfaceInteraction, SharesOfTheRowsSumToTheWhole) {
  // The four cubes of the test above (and the far one) split into the cells' shares of
  // three ranks, {0, 3}, {} and {1, 2, 4} (ImmersedCoupling::share_cells: the cells whose
  // centroid each rank holds, so neither contiguous nor balanced): the forces,
  // energies and stiffness actions of the shares sum to the whole list's, to round-off,
  // for full and half lists; the elastic forces and energies of CellPopulation::share_work
  // the same.
  Scene scene({{0, 0, 0}, {2.6, 0.2, 0}, {0.3, 3.4, 0.5}, {2.5, 2.6, -0.2}, {30, 0, 0}}, 3);
  scene.jitter(5, 0.1);
  const MorsePotential potential = test_potential();
  const int nodes = scene.cells->num_nodes();
  CellPopulation::NodeVectors moves("moves", nodes);
  {
    auto m = Kokkos::create_mirror_view(moves);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int n = 0; n < nodes; ++n)
      for (int d = 0; d < 3; ++d) m(n, d) = unit(rng);
    Kokkos::deep_copy(moves, m);
  }
  const std::vector<std::vector<int>> shares{{0, 3}, {}, {1, 2, 4}};
  // max |Σ shares − whole| / max |whole| over the nodes' vectors
  auto relative_gap = [](const std::vector<Eigen::Vector3d>& whole, const std::vector<Eigen::Vector3d>& summed) {
    double gap = 0.0, largest = 0.0;
    for (std::size_t n = 0; n < whole.size(); ++n) {
      gap = std::max(gap, (whole[n] - summed[n]).norm());
      largest = std::max(largest, whole[n].norm());
    }
    return gap / largest;
  };
  auto to_vectors = [&](const CellPopulation::ConstNodeVectors& v) {
    const auto h = host_copy(v);
    std::vector<Eigen::Vector3d> result(nodes);
    for (int n = 0; n < nodes; ++n) result[n] = Eigen::Vector3d(h(n, 0), h(n, 1), h(n, 2));
    return result;
  };
  for (const bool half : {false, true}) {
    SurfaceInteraction whole = make_interaction(*scene.cells, potential, 0.3, half);
    const double whole_energy = whole.compute_forces_and_energy();
    const std::vector<Eigen::Vector3d> whole_forces = node_forces(*scene.cells, whole);
    whole.linearize();
    CellPopulation::NodeVectors change("change", nodes);
    whole.force_change(moves, change);
    const std::vector<Eigen::Vector3d> whole_change = to_vectors(change);

    double energy = 0.0;
    std::vector<Eigen::Vector3d> forces(nodes, Eigen::Vector3d::Zero()), changes(nodes, Eigen::Vector3d::Zero());
    for (const std::vector<int>& cells : shares) {
      SurfaceInteraction share = make_interaction(*scene.cells, potential, 0.3, half);
      share.share_rows(cells);
      energy += share.compute_forces_and_energy();
      // A share bins the points of its cells and their partners alone: none for no cells,
      // and never the far cube (cell 4).
      EXPECT_LE(share.active_cell_count(), cells.empty() ? 0 : 4);
      const std::vector<Eigen::Vector3d> f = node_forces(*scene.cells, share);
      share.linearize();
      share.force_change(moves, change);
      const std::vector<Eigen::Vector3d> k = to_vectors(change);
      for (int n = 0; n < nodes; ++n) forces[n] += f[n], changes[n] += k[n];
    }
    std::printf("  %s list: shares against the whole, forces %.1e, stiffness action %.1e, energy %.1e\n",
                half ? "half" : "full", relative_gap(whole_forces, forces), relative_gap(whole_change, changes),
                std::fabs(energy / whole_energy - 1.0));
    EXPECT_LT(relative_gap(whole_forces, forces), 1e-14);
    EXPECT_LT(relative_gap(whole_change, changes), 1e-14);
    EXPECT_NEAR(energy / whole_energy, 1.0, 1e-14);
  }
  // The elastic work: the same cubes with a neo-Hookean material, two of them with area
  // and volume constraints, strained by a jitter.
  std::vector<PlacedCell> placed(scene.meshes.size());
  for (std::size_t c = 0; c < placed.size(); ++c) {
    placed[c].mesh = &scene.meshes[c];
    placed[c].center = {3.0 * c, 0.0, 0.0};
    placed[c].material = NeoHookeanMaterial::from_moduli(10.0, 50.0);
    placed[c].area_modulus = c % 2 ? 5.0 : 0.0;
    placed[c].volume_modulus = c % 2 ? 20.0 : 0.0;
  }
  CellPopulation elastic(placed);
  {
    auto x = host_copy(elastic.positions());
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-0.05, 0.05);
    for (std::size_t n = 0; n < x.extent(0); ++n)
      for (int i = 0; i < 3; ++i) x(n, i) += u(rng);
    elastic.set_positions(x);
  }
  const double whole_energy = elastic.compute_internal_forces_and_energy();
  const std::vector<Eigen::Vector3d> whole_forces = to_vectors(elastic.internal_forces());
  double energy = 0.0;
  std::vector<Eigen::Vector3d> forces(nodes, Eigen::Vector3d::Zero());
  for (const std::vector<int>& cells : shares) {
    elastic.share_work(cells);
    energy += elastic.compute_internal_forces_and_energy();
    const std::vector<Eigen::Vector3d> f = to_vectors(elastic.internal_forces());
    for (int n = 0; n < nodes; ++n) forces[n] += f[n];
  }
  std::printf("  elastic: shares against the whole, forces %.1e, energy %.1e\n", relative_gap(whole_forces, forces),
              std::fabs(energy / whole_energy - 1.0));
  EXPECT_LT(relative_gap(whole_forces, forces), 1e-14);
  EXPECT_NEAR(energy / whole_energy, 1.0, 1e-14);
  EXPECT_THROW(elastic.share_work({3, 5}), std::invalid_argument);  // no cell 5
  EXPECT_THROW(elastic.share_work({2, 1}), std::invalid_argument);  // out of order
}

TEST(SurfaceInteraction, ObeysNewtonsThirdLaw) {
  Scene scene({{0, 0, 0}, {2.5, 0.3, 0.1}}, 7);
  scene.jitter(9, 0.1);
  SurfaceInteraction interaction = make_interaction(*scene.cells, test_potential(), 0.3, false);
  interaction.compute_forces();
  const auto f = host_copy(interaction.forces());
  const auto cell = host_copy(interaction.point_cell());
  Eigen::Vector3d on_cell[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  double magnitude = 0.0;
  for (int i = 0; i < interaction.num_points(); ++i) {
    const Eigen::Vector3d fi(f(i, 0), f(i, 1), f(i, 2));
    on_cell[cell(i)] += fi;
    magnitude += fi.norm();
  }
  std::cout << "  force on cell 0 " << on_cell[0].transpose() << " pN, on cell 1 " << on_cell[1].transpose()
            << " pN; sum " << (on_cell[0] + on_cell[1]).norm() << " (Σ|f| = " << magnitude << ")\n";
  EXPECT_GT(on_cell[0].norm(), 1e-3 * magnitude);
  EXPECT_LT((on_cell[0] + on_cell[1]).norm(), 1e-14 * magnitude);
}

TEST(SurfaceInteraction, ForcesAreMinusTheGradientOfTheEnergy) {
  // The nodal forces against central differences of E in the node positions, for nodal
  // quadrature and for Gauss points on the triangles (whose forces reach the nodes
  // through the shape functions).
  Scene scene({{0, 0, 0}, {2.4, 0.2, 0.1}}, 11);
  scene.jitter(13, 0.1);
  for (const auto quadrature : {SurfaceQuadrature::nodes, SurfaceQuadrature::gauss3}) {
    SurfaceInteraction interaction = make_interaction(*scene.cells, test_potential(), 0.5, false, quadrature);
    const auto x = host_copy(scene.cells->positions());
    interaction.compute_forces();
    const std::vector<Eigen::Vector3d> f = node_forces(*scene.cells, interaction);
    const double step = 1e-6;
    double error = 0.0, norm = 0.0;
    for (int n = 0; n < scene.cells->num_nodes(); n += 5)
      for (int c = 0; c < 3; ++c) {
        double energy[2];
        for (int side = 0; side < 2; ++side) {
          auto shifted = host_copy(x);
          shifted(n, c) += side == 0 ? step : -step;
          scene.cells->set_positions(shifted);
          energy[side] = interaction.compute_forces_and_energy();
        }
        const double derivative = -(energy[0] - energy[1]) / (2 * step);
        error += std::pow(derivative - f[n][c], 2);
        norm += f[n][c] * f[n][c];
      }
    scene.cells->set_positions(x);
    std::cout << "  " << (quadrature == SurfaceQuadrature::nodes ? "nodal quadrature" : "3 Gauss points")
              << ": nodal force vs −∂E/∂x (central differences): relative error " << std::sqrt(error / norm) << "\n";
    EXPECT_LT(std::sqrt(error / norm), 1e-6);
  }
}

// The serial reference of the interaction's stiffness: δf_n = Σ_{p,k: n_pk = n} s_pk δF_p,
// δF_p = Σ_q over points of other cells within r_c of the Hessian blocks
//   w_p w_q [ (f/r) δd + (f' − f/r) (d̂·δd) d̂ ],   δd = δx_p − δx_q,   δx_p = Σ_k s_pk δx_{n_pk},
// with f' by a central difference of the law (so the kernel's closed form is checked too).
std::vector<Eigen::Vector3d> brute_force_force_change(const CellPopulation& cells, SurfaceInteraction& interaction,
                                                      const MorsePotential& potential,
                                                      const std::vector<Eigen::Vector3d>& node_moves) {
  interaction.gather_point_positions();
  const auto x = host_copy(interaction.point_positions());
  const auto weight = host_copy(interaction.point_weight());
  const auto cell = host_copy(interaction.point_cell());
  const auto nodes = host_copy(interaction.point_nodes());
  const auto shape = host_copy(interaction.point_shape());
  const int n = interaction.num_points();
  std::vector<Eigen::Vector3d> moves(n, Eigen::Vector3d::Zero()), changes(n, Eigen::Vector3d::Zero());
  for (int p = 0; p < n; ++p)
    for (int k = 0; k < 3; ++k) moves[p] += shape(p, k) * node_moves[nodes(p, k)];
  for (int p = 0; p < n; ++p)
    for (int q = 0; q < n; ++q) {
      if (cell(p) == cell(q)) continue;
      const Eigen::Vector3d d(x(p, 0) - x(q, 0), x(p, 1) - x(q, 1), x(p, 2) - x(q, 2));
      const double r = d.norm();
      if (r >= potential.cutoff) continue;
      const Eigen::Vector3d unit = d / r, dd = moves[p] - moves[q];
      const double f = potential.force(r);
      const double slope = (potential.force(r + 1e-6) - potential.force(r - 1e-6)) / 2e-6;
      changes[p] += weight(p) * weight(q) * (f / r * dd + (slope - f / r) * unit.dot(dd) * unit);
    }
  std::vector<Eigen::Vector3d> result(cells.num_nodes(), Eigen::Vector3d::Zero());
  for (int p = 0; p < n; ++p)
    for (int k = 0; k < 3; ++k) result[nodes(p, k)] += shape(p, k) * changes[p];
  return result;
}

TEST(SurfaceInteraction, ForceChangeIsTheExactLinearizationOfTheForces) {
  // Three cubes 0.3–1.5 μm apart, turned and jittered, random node moves δx. For full and
  // half lists, nodal quadrature and 3 Gauss points per triangle, K δx from linearize() and
  // force_change() against
  //   a serial double loop over the pairs' Hessian blocks (to round-off, 1e-9: its f' is a
  //   central difference of the law, good to about 1e-10),
  //   a central difference of the forces, [F(x + εδx) − F(x − εδx)] / 2ε with
  //   ε max|δx| = 1e-5 μm (truncation ≈ (ε|δx| β)² ≈ 2e-9; measured 2e-9, and 3e-10 with
  //   Gauss points), to 1e-8,
  // and ⟨δy, K δx⟩ = ⟨δx, K δy⟩ (K is symmetric: minus a Hessian) to 1e-12.
  Scene scene({{0, 0, 0}, {2.5, 0.3, 0.1}, {0.2, 2.6, -0.3}}, 19);
  scene.jitter(23, 0.1);
  // The cut-off at 5 μm: the law's slope jumps there by f'(r_c) ≈ 1e-8 De β², so no pair
  // that crosses r_c within the central difference spoils it (at r_c = 3 μm, where the jump
  // is 3e-5 De β², one Gauss-point pair within 3e-6 μm of r_c moves it by 1.3e-7).
  const MorsePotential potential{1.0, 4.0, 0.25, 5.0};
  const int nodes = scene.cells->num_nodes();
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  auto random_moves = [&] {
    std::vector<Eigen::Vector3d> moves(nodes);
    for (auto& m : moves) m = Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    return moves;
  };
  const std::vector<Eigen::Vector3d> move_x = random_moves(), move_y = random_moves();
  auto to_view = [&](const std::vector<Eigen::Vector3d>& moves) {
    CellPopulation::NodeVectors v("node_moves", nodes);
    auto h = Kokkos::create_mirror_view(v);
    for (int n = 0; n < nodes; ++n)
      for (int c = 0; c < 3; ++c) h(n, c) = moves[n][c];
    Kokkos::deep_copy(v, h);
    return v;
  };
  auto relative = [](const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
    double error = 0.0, norm = 0.0;
    for (std::size_t n = 0; n < a.size(); ++n) error += (a[n] - b[n]).squaredNorm(), norm += b[n].squaredNorm();
    return std::sqrt(error / norm);
  };
  const auto x0 = host_copy(scene.cells->positions());
  for (const auto quadrature : {SurfaceQuadrature::nodes, SurfaceQuadrature::gauss3})
    for (const bool half : {false, true}) {
      SurfaceInteraction interaction = make_interaction(*scene.cells, potential, 0.3, half, quadrature);
      interaction.linearize();
      auto change_of = [&](const std::vector<Eigen::Vector3d>& moves) {
        CellPopulation::NodeVectors change("force_change", nodes);
        interaction.force_change(to_view(moves), change);
        const auto h = host_copy(change);
        std::vector<Eigen::Vector3d> result(nodes);
        for (int n = 0; n < nodes; ++n) result[n] = Eigen::Vector3d(h(n, 0), h(n, 1), h(n, 2));
        return result;
      };
      const std::vector<Eigen::Vector3d> Kx = change_of(move_x), Ky = change_of(move_y);
      const double against_serial = relative(Kx, brute_force_force_change(*scene.cells, interaction, potential, move_x));

      const double epsilon = 1e-5;  // max |δx| = 1
      std::vector<Eigen::Vector3d> side[2];
      for (int s = 0; s < 2; ++s) {
        auto moved = host_copy(x0);
        for (int n = 0; n < nodes; ++n)
          for (int c = 0; c < 3; ++c) moved(n, c) += (s == 0 ? epsilon : -epsilon) * move_x[n][c];
        scene.cells->set_positions(moved);
        interaction.compute_forces();
        side[s] = node_forces(*scene.cells, interaction);
      }
      scene.cells->set_positions(x0);
      std::vector<Eigen::Vector3d> difference(nodes);
      for (int n = 0; n < nodes; ++n) difference[n] = (side[0][n] - side[1][n]) / (2 * epsilon);
      const double against_difference = relative(Kx, difference);

      double yKx = 0.0, xKy = 0.0, scale = 0.0;
      for (int n = 0; n < nodes; ++n) {
        yKx += move_y[n].dot(Kx[n]);
        xKy += move_x[n].dot(Ky[n]);
        scale += move_y[n].norm() * Kx[n].norm();
      }
      std::cout << "  " << (quadrature == SurfaceQuadrature::nodes ? "nodal quadrature, " : "3 Gauss points, ")
                << (half ? "half" : "full") << " list: K dx vs serial pair Hessians " << against_serial
                << ", vs central difference of the forces " << against_difference << "; asymmetry "
                << std::fabs(yKx - xKy) / scale << "\n";
      EXPECT_LT(against_serial, 1e-9);
      EXPECT_LT(against_difference, 1e-8);
      EXPECT_LT(std::fabs(yKx - xKy), 1e-12 * scale);
    }
}

TEST(SurfaceInteraction, TheSkinChangesOnlyTheRebuildCount) {
  // The same motion (small random steps) with skins 0.05 and 1 μm: the same forces at
  // every step, many rebuilds with the thin skin, one with the thick.
  const MorsePotential potential = test_potential();
  std::vector<std::vector<double>> forces[2];
  int rebuilds[2];
  const double skins[2] = {0.05, 1.0};
  for (int s = 0; s < 2; ++s) {
    Scene scene({{0, 0, 0}, {2.6, 0.2, 0}, {0.3, 3.4, 0.5}}, 17);
    SurfaceInteraction interaction = make_interaction(*scene.cells, potential, skins[s], false);
    for (int step = 0; step < 10; ++step) {
      scene.jitter(100 + step, 0.03);
      interaction.compute_forces();
      const auto f = host_copy(interaction.forces());
      forces[s].emplace_back(f.data(), f.data() + f.size());
    }
    rebuilds[s] = interaction.rebuild_count();
  }
  double worst = 0.0;
  for (std::size_t step = 0; step < forces[0].size(); ++step)
    for (std::size_t k = 0; k < forces[0][step].size(); ++k)
      worst = std::max(worst, std::fabs(forces[0][step][k] - forces[1][step][k]));
  std::cout << "  rebuilds: skin 0.05 μm " << rebuilds[0] << ", skin 1 μm " << rebuilds[1]
            << "; largest force difference " << worst << " pN\n";
  EXPECT_EQ(rebuilds[1], 1);
  EXPECT_GT(rebuilds[0], 3);
  EXPECT_LT(worst, 1e-12);
}

// Two parallel plates (faces of thin blocks) at gap h. The force per area on a point above
// an infinite plate within the cut-off: p(h) = ∫ f(r) (h/r) dA′ = 2π h ∫_h^{r_c} f(r) dr
// = 2π h [φ(h) − φ(r_c)] (positive: repulsion).
double plate_pressure(const MorsePotential& m, double gap) {
  return 2.0 * M_PI * gap * (m.energy(gap) - m.energy(m.cutoff));
}

TEST(SurfaceInteraction, PlatesMatchThePlatePlateIntegral) {
  // Blocks 12 × 12 × 3.5 μm (the far faces beyond the cut-off), facing faces at gap h; at
  // the central node of the lower block's top face, F_z / w (its area weight) against
  // p(h) under refinement, with nodal quadrature and with 3 and 6 Gauss points per triangle.
  const MorsePotential potential = test_potential();
  const double exact = plate_pressure(potential, 0.5);
  double finest_error[3] = {0, 0, 0}, coarsest_error[3] = {0, 0, 0};
  const SurfaceQuadrature rules[3] = {SurfaceQuadrature::nodes, SurfaceQuadrature::gauss3, SurfaceQuadrature::gauss6};
  const char* names[3] = {"nodes", "3 Gauss points", "6 Gauss points"};
  for (int r = 0; r < 3; ++r) {
    double previous_error = 1e300;
    // (Gauss points are 3 or 6 per triangle: two refinements suffice.)
    for (const int n : r == 0 ? std::vector<int>{12, 24, 48} : std::vector<int>{12, 24}) {
      const CellMesh block = testing::tetrahedral_block({n, n, 2}, {12.0, 12.0, 3.5});
      std::vector<PlacedCell> placed(2);
      for (int c = 0; c < 2; ++c) {
        placed[c].mesh = &block;
        placed[c].center = {0.0, 0.0, c == 0 ? -1.75 : 1.75 + 0.5};
      }
      CellPopulation cells(placed);
      SurfaceInteraction interaction = make_interaction(cells, potential, 0.2, true, rules[r]);
      interaction.compute_forces();
      const std::vector<Eigen::Vector3d> f = node_forces(cells, interaction);
      const auto w = host_copy(cells.surface_area_weights());
      const auto x = host_copy(cells.positions());
      double pressure = NAN;
      for (int n_i = 0; n_i < cells.num_nodes(); ++n_i)
        if (std::fabs(x(n_i, 0)) < 1e-9 && std::fabs(x(n_i, 1)) < 1e-9 && std::fabs(x(n_i, 2)) < 1e-9)
          pressure = -f[n_i][2] / w(n_i);  // the lower plate's node is pushed down (−z) by repulsion
      const double error = std::fabs(pressure - exact) / std::fabs(exact);
      std::cout << "  plates at gap 0.5 μm, " << names[r] << ", node spacing " << 12.0 / n << " μm: pressure "
                << pressure << " Pa (exact " << exact << "), relative error " << error << "\n";
      EXPECT_LT(error, previous_error);
      if (n == 12) coarsest_error[r] = error;
      previous_error = finest_error[r] = error;
    }
    EXPECT_LT(finest_error[r], 0.01);
  }
  // Gauss points resolve what coarse nodes cannot.
  EXPECT_LT(coarsest_error[1], 0.5 * coarsest_error[0]);
  EXPECT_LT(coarsest_error[2], coarsest_error[1]);
}

TEST(SurfaceInteraction, TwoRigidCellsSettleAtTheMorseMinimum) {
  // Two blocks face to face (4 × 4 μm faces, nodes 0.25 μm = 1/β apart) moved as rigid
  // bodies along z by the interaction alone, with an overdamped mobility (Δh = m F_z,
  // steps of at most 0.02 μm), from 1 μm apart: they settle where the interaction energy
  // E(h) of the two discrete surfaces has its minimum, found independently by a
  // golden-section search on E. (Soft Morse repulsion: rigid bodies have that minimum
  // only near contact of flat faces; the blocks' edges move it from the infinite plates'
  // h* = r0 − ln 2/β, printed for comparison.)
  const MorsePotential potential = test_potential();
  const CellMesh block = testing::tetrahedral_block({16, 16, 2}, {4.0, 4.0, 3.5});
  std::vector<PlacedCell> placed(2);
  const double start_gap = 1.0;
  for (int c = 0; c < 2; ++c) {
    placed[c].mesh = &block;
    placed[c].center = {0.0, 0.0, c == 0 ? -1.75 : 1.75 + start_gap};
  }
  CellPopulation cells(placed);
  SurfaceInteraction interaction = make_interaction(cells, potential, 0.3, true);
  const auto point_cell = host_copy(interaction.point_cell());
  const auto cell = host_copy(cells.node_cell());
  const auto reference = host_copy(cells.reference_positions());
  // Places the upper block at gap h; returns E, and F_z on the upper block.
  auto place = [&](double gap, double& force_on_upper) {
    auto x = host_copy(reference);
    for (std::size_t n = 0; n < x.extent(0); ++n)
      if (cell(n) == 1) x(n, 2) += gap - start_gap;
    cells.set_positions(x);
    const double energy = interaction.compute_forces_and_energy();
    const auto f = host_copy(interaction.forces());
    force_on_upper = 0.0;
    for (int i = 0; i < interaction.num_points(); ++i)
      if (point_cell(i) == 1) force_on_upper += f(i, 2);
    return energy;
  };
  // Stable while mobility × the contact stiffness (≈ 600 pN/μm here) stays below 2.
  const double mobility = 5e-4;  // [μm/pN]
  double gap = start_gap, force = 0.0;
  int iterations = 0;
  for (; iterations < 1000; ++iterations) {
    place(gap, force);
    const double step = std::clamp(mobility * force, -0.02, 0.02);
    gap += step;
    if (std::fabs(step) < 1e-10) break;
  }
  double low = 0.02, high = 0.5, unused = 0.0;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < 60; ++k) {
    const double a = high - golden * (high - low), b = low + golden * (high - low);
    if (place(a, unused) < place(b, unused))
      high = b;
    else
      low = a;
  }
  const double least_energy_gap = 0.5 * (low + high);
  std::cout << "  two rigid blocks settle at a gap of " << gap << " μm after " << iterations
            << " steps; least interaction energy at " << least_energy_gap << " μm (infinite plates: r0 − ln2/β = "
            << 0.25 - std::log(2.0) / 4.0 << " μm); " << interaction.rebuild_count() << " list rebuilds\n";
  EXPECT_LT(iterations, 1000);
  EXPECT_NEAR(gap, least_energy_gap, 1e-5);
  EXPECT_GT(gap, 0.0);
  EXPECT_LT(gap, potential.zero_force_length);
}

}  // namespace
}  // namespace rouleau
