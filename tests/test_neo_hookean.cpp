// The neo-Hookean solid (paper eqs. 2, 9, 10) on 4-node tetrahedra, with and without the
// strain-hardening term C3 (J1 − 3)³, the global area constraint of a cell, and the cells'
// surface measures, against exact facts, finite differences and a plain serial reference.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Kokkos_Core.hpp>
#include <cmath>
#include <iostream>
#include <random>

#include "cells/cell_population.hpp"
#include "kernels/neo_hookean.hpp"
#include "test_helpers.hpp"
#include "tet_box_mesh.hpp"

namespace rouleau {
namespace {

// The default execution space's population (the one a run uses); the Serial one for the
// thread-count comparison (host builds only: a CUDA build instantiates only Cuda).
using Population = CellPopulation;

// A red-cell-membrane-like material: G = 11.67 Pa, K from ν = 0.45.
const double shear_modulus = 4.2 / 0.36;
const double bulk_modulus = 2.0 * shear_modulus * 1.45 / (3.0 * 0.1);
const NeoHookeanMaterial material = NeoHookeanMaterial::from_moduli(shear_modulus, bulk_modulus);
// The same with Mills et al. 2004's strain hardening, C3 = G/30, and with an exaggerated
// one, C3 = 3G, where the C3 term dominates the stress at the tests' strains.
const NeoHookeanMaterial mills_material = NeoHookeanMaterial::from_moduli(shear_modulus, bulk_modulus, 1.0 / 30.0);
const NeoHookeanMaterial hardening_material = NeoHookeanMaterial::from_moduli(shear_modulus, bulk_modulus, 3.0);

Mat3 to_mat3(const Eigen::Matrix3d& a) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.m[i][j] = a(i, j);
  return m;
}
Eigen::Matrix3d to_eigen(const Mat3& a) {
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = a.m[i][j];
  return m;
}
Eigen::Matrix3d random_deformation_gradient(std::mt19937& rng, double amplitude) {
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) f(i, j) += u(rng);
  return f;
}
Eigen::Matrix3d rotation(double angle, Eigen::Vector3d axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// The reference stress by another route: S = 2 ∂W/∂C, with ∂I1/∂C = I, ∂I3/∂C = I3 C⁻¹,
// ∂J1/∂C = J^(−2/3) (I − I1/3 C⁻¹), and C1' = C1 + 3 C3 (J1 − 3)²:
//   S = 2 C1' J^(−2/3) (I − I1/3 C⁻¹) + C2 J (J − 1) C⁻¹,   P = F S,   σ = J⁻¹ F S Fᵀ.
Eigen::Matrix3d reference_first_piola(const Eigen::Matrix3d& f, const NeoHookeanMaterial& m) {
  const Eigen::Matrix3d c = f.transpose() * f;
  const double j = f.determinant();
  const double i1 = c.trace();
  const double j1 = i1 * std::pow(j, -2.0 / 3.0);
  const double c1 = m.c1 + 3.0 * m.c3 * (j1 - 3.0) * (j1 - 3.0);
  const Eigen::Matrix3d c_inverse = c.inverse();
  const Eigen::Matrix3d s = 2.0 * c1 * std::pow(j, -2.0 / 3.0) * (Eigen::Matrix3d::Identity() - i1 / 3.0 * c_inverse) +
                            m.c2 * j * (j - 1.0) * c_inverse;
  return f * s;
}
// W = C1 (J1 − 3) + C3 (J1 − 3)³ + C2/2 (J − 1)², written out with Eigen.
double reference_energy_density(const Eigen::Matrix3d& f, const NeoHookeanMaterial& m) {
  const double j = f.determinant();
  const double j1 = (f.transpose() * f).trace() * std::pow(j, -2.0 / 3.0);
  return m.c1 * (j1 - 3.0) + m.c3 * std::pow(j1 - 3.0, 3) + 0.5 * m.c2 * (j - 1.0) * (j - 1.0);
}

TEST(NeoHookeanMaterial, StressIsTheDerivativeOfTheEnergyDensity) {
  // P = ∂W/∂F by central differences of W, step 1e-6, for the paper's law and with the
  // strain-hardening term (Mills' C3 = G/30 and C3 = 3G).
  for (const NeoHookeanMaterial& m : {material, mills_material, hardening_material}) {
    NeoHookeanMaterial without_hardening = m;
    without_hardening.c3 = 0.0;
    std::mt19937 rng(7);
    double worst = 0.0, hardening_share = 0.0;
    for (int sample = 0; sample < 20; ++sample) {
      const Eigen::Matrix3d f = random_deformation_gradient(rng, 0.3);
      const Mat3 p = m.first_piola(to_mat3(f));
      const Eigen::Matrix3d hardening_part = to_eigen(p) - to_eigen(without_hardening.first_piola(to_mat3(f)));
      hardening_share = std::max(hardening_share, hardening_part.norm() / to_eigen(p).norm());
      const double step = 1e-6;
      double error = 0.0, norm = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Eigen::Matrix3d plus = f, minus = f;
          plus(i, j) += step;
          minus(i, j) -= step;
          const double derivative =
              (m.energy_density(to_mat3(plus)) - m.energy_density(to_mat3(minus))) / (2 * step);
          error += std::pow(derivative - p.m[i][j], 2);
          norm += p.m[i][j] * p.m[i][j];
        }
      worst = std::max(worst, std::sqrt(error / norm));
    }
    std::cout << "  C3/G = " << m.c3 / shear_modulus << ": P vs central-difference ∂W/∂F: worst relative error "
              << worst << " (the C3 term up to " << hardening_share << " of |P|)\n";
    EXPECT_LT(worst, 1e-6);
    if (m.c3 > 0.0) EXPECT_GT(hardening_share, m.c3 > shear_modulus ? 0.3 : 1e-3);  // the term is exercised
  }
}

TEST(NeoHookeanMaterial, StressMatchesTheSecondPiolaKirchhoffRoute) {
  for (const NeoHookeanMaterial& m : {material, mills_material, hardening_material}) {
    std::mt19937 rng(11);
    double worst = 0.0, worst_energy = 0.0;
    for (int sample = 0; sample < 50; ++sample) {
      const Eigen::Matrix3d f = random_deformation_gradient(rng, 0.4);
      const Eigen::Matrix3d expected = reference_first_piola(f, m);
      worst = std::max(worst, (to_eigen(m.first_piola(to_mat3(f))) - expected).norm() / expected.norm());
      worst_energy =
          std::max(worst_energy, std::fabs(m.energy_density(to_mat3(f)) / reference_energy_density(f, m) - 1.0));
    }
    std::cout << "  C3/G = " << m.c3 / shear_modulus << ": P vs F·S (2 ∂W/∂C): worst relative difference " << worst
              << ", W vs the written-out W " << worst_energy << "\n";
    EXPECT_LT(worst, 1e-13);
    EXPECT_LT(worst_energy, 1e-12);
  }
}

TEST(NeoHookeanMaterial, SmallStrainsRecoverTheShearAndBulkModuli) {
  // Linear elasticity: σ = 2G ε_dev + K tr(ε) I. Uniaxial strain ε along x:
  //   σ_xx = (K + 4G/3) ε, σ_yy = (K − 2G/3) ε  ⇒  G = (σ_xx − σ_yy)/(2ε), K = (σ_xx + 2σ_yy)/(3ε);
  // simple shear γ: σ_xy = G γ; hydrostatic stretch (1+ε)I: σ_ii = 3K ε.
  // The C3 term is of fourth order in the strain: the moduli are the same with it.
  for (const NeoHookeanMaterial& m : {material, hardening_material}) {
    const double strain = 1e-7;
    Mat3 uniaxial = Mat3::identity();
    uniaxial.m[0][0] += strain;
    const Mat3 sigma = m.cauchy_stress(uniaxial);
    const double g_uniaxial = (sigma.m[0][0] - sigma.m[1][1]) / (2.0 * strain);
    const double k_uniaxial = (sigma.m[0][0] + 2.0 * sigma.m[1][1]) / (3.0 * strain);
    Mat3 shear = Mat3::identity();
    shear.m[0][1] = strain;
    const double g_shear = m.cauchy_stress(shear).m[0][1] / strain;
    Mat3 hydrostatic = Mat3::identity();
    for (int i = 0; i < 3; ++i) hydrostatic.m[i][i] += strain;
    const double k_hydrostatic = m.cauchy_stress(hydrostatic).m[0][0] / (3.0 * strain);
    std::cout << "  C3/G = " << m.c3 / shear_modulus << ": uniaxial: G " << g_uniaxial << " K " << k_uniaxial
              << "; simple shear G " << g_shear << "; hydrostatic K " << k_hydrostatic << " (exact G "
              << shear_modulus << ", K " << bulk_modulus << ")\n";
    // The O(ε) nonlinear terms relative to the moduli are ~ε·K/G ≈ 1e-6.
    EXPECT_NEAR(g_uniaxial / shear_modulus, 1.0, 1e-5);
    EXPECT_NEAR(k_uniaxial / bulk_modulus, 1.0, 1e-5);
    EXPECT_NEAR(g_shear / shear_modulus, 1.0, 1e-5);
    EXPECT_NEAR(k_hydrostatic / bulk_modulus, 1.0, 1e-5);
  }
}

// ---- the element kernel on whole meshes

// The node vectors (node, 3) of a View as one flat host array (node-major).
template <class View>
Kokkos::View<double*, Kokkos::HostSpace> flat(const View& v) {
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v);
  Kokkos::View<double*, Kokkos::HostSpace> out("flat", 3 * host.extent(0));
  for (std::size_t n = 0; n < host.extent(0); ++n)
    for (int i = 0; i < 3; ++i) out(3 * n + i) = host(n, i);
  return out;
}

// A host copy of a View that never aliases it (create_mirror_view would, on the host).
template <class View>
auto host_copy(const View& v) {
  auto copy = Kokkos::create_mirror(Kokkos::HostSpace(), v);
  Kokkos::deep_copy(copy, v);
  return copy;
}

// Sets the current positions to map(reference position) for every node.
template <class Population, class Map>
void deform(Population& cells, Map map) {
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.reference_positions());
  auto x = Kokkos::create_mirror_view(cells.positions());
  for (std::size_t n = 0; n < x0.extent(0); ++n) {
    const Eigen::Vector3d y = map(Eigen::Vector3d(x0(n, 0), x0(n, 1), x0(n, 2)));
    for (int i = 0; i < 3; ++i) x(n, i) = y[i];
  }
  cells.set_positions(x);
}

std::vector<PlacedCell> one_cell(const CellMesh& mesh, Eigen::Vector3d center = Eigen::Vector3d::Zero(),
                                 const NeoHookeanMaterial& cell_material = material, double area_modulus = 0.0,
                                 double volume_modulus = 0.0) {
  PlacedCell cell;
  cell.mesh = &mesh;
  cell.material = cell_material;
  cell.area_modulus = area_modulus;
  cell.volume_modulus = volume_modulus;
  for (int i = 0; i < 3; ++i) cell.center[i] = center[i];
  return {cell};
}

// A random smooth-ish deformation: an affine part plus random nodal jitter.
template <class Population>
void deform_randomly(Population& cells, std::uint32_t seed, double jitter) {
  std::mt19937 rng(seed);
  const Eigen::Matrix3d f = random_deformation_gradient(rng, 0.2);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  deform(cells, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(f * x + Eigen::Vector3d(u(rng), u(rng), u(rng))); });
}

// max over 30 nodes' coordinates of the relative error of f against −∂E/∂x by central
// differences of E (E = Σ V0 W + E_A, compute_internal_forces_and_energy).
double force_vs_energy_gradient(Population& cells, double step = 1e-6) {
  cells.compute_internal_forces();
  const auto force = host_copy(cells.internal_forces());
  const auto x = host_copy(cells.positions());
  double error = 0.0, norm = 0.0;
  for (int node = 0; node < cells.num_nodes(); node += std::max(1, cells.num_nodes() / 30))
    for (int i = 0; i < 3; ++i) {
      double energy[2];
      for (int side = 0; side < 2; ++side) {
        auto shifted = host_copy(x);
        shifted(node, i) += side == 0 ? step : -step;
        cells.set_positions(shifted);
        energy[side] = cells.compute_internal_forces_and_energy();
      }
      const double derivative = -(energy[0] - energy[1]) / (2 * step);
      error += std::pow(derivative - force(node, i), 2);
      norm += force(node, i) * force(node, i);
    }
  cells.set_positions(x);
  return std::sqrt(error / norm);
}

TEST(NeoHookeanForces, AreMinusTheGradientOfTheStrainEnergy) {
  // f = −∂E/∂x by central differences of E = Σ V0 W at every coordinate of 30 nodes, for
  // the paper's law and with strain hardening.
  const CellMesh mesh = testing::tetrahedral_box(3, 3.0);
  for (const NeoHookeanMaterial& m : {material, mills_material, hardening_material}) {
    Population cells(one_cell(mesh, Eigen::Vector3d::Zero(), m));
    deform_randomly(cells, 3, 0.08);
    const double relative = force_vs_energy_gradient(cells);
    std::cout << "  C3/G = " << m.c3 / shear_modulus
              << ": nodal force vs −∂E/∂x (central differences): relative error " << relative << "\n";
    EXPECT_LT(relative, 1e-6);
  }
}

TEST(NeoHookeanForces, RigidMotionsGiveNoForceAndNoEnergy) {
  const CellMesh mesh = testing::tetrahedral_box(3, 3.0);
  Population cells(one_cell(mesh, {5.0, -2.0, 1.0}));
  const Eigen::Vector3d shift(0.3, -7.0, 2.5);
  double worst_force = 0.0, worst_energy = 0.0;
  for (const double angle : {0.0, 0.1, 1.0, M_PI / 2, 2.5, M_PI}) {
    const Eigen::Matrix3d r = rotation(angle, Eigen::Vector3d(1.0, -2.0, 0.5));
    deform(cells, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(r * x + shift); });
    const double energy = cells.compute_internal_forces_and_energy();
    auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.internal_forces());
    for (int n = 0; n < cells.num_nodes(); ++n)
      for (int i = 0; i < 3; ++i) worst_force = std::max(worst_force, std::fabs(f(n, i)));
    worst_energy = std::max(worst_energy, std::fabs(energy));
  }
  // Scale: a unit strain on an element of size 1 μm gives forces of order G·1 μm² ≈ 10 pN.
  std::cout << "  rigid motions: largest nodal force " << worst_force << " pN, largest energy " << worst_energy
            << " pN·μm\n";
  EXPECT_LT(worst_force, 1e-11 * shear_modulus);
  EXPECT_LT(worst_energy, 1e-11 * shear_modulus);
}

TEST(NeoHookeanForces, AreObjective) {
  // Rotating a deformed body rotates its forces and keeps its energy: f(Qx) = Q f(x).
  const CellMesh mesh = testing::tetrahedral_box(3, 3.0);
  Population cells(one_cell(mesh));
  deform_randomly(cells, 5, 0.1);
  const double energy = cells.compute_internal_forces_and_energy();
  const auto x = host_copy(cells.positions());
  const auto f = host_copy(cells.internal_forces());
  const Eigen::Matrix3d q = rotation(2.2, Eigen::Vector3d(0.3, 1.0, -0.7));
  auto rotated = host_copy(cells.positions());
  for (int n = 0; n < cells.num_nodes(); ++n) {
    const Eigen::Vector3d y = q * Eigen::Vector3d(x(n, 0), x(n, 1), x(n, 2));
    for (int i = 0; i < 3; ++i) rotated(n, i) = y[i];
  }
  cells.set_positions(rotated);
  const double rotated_energy = cells.compute_internal_forces_and_energy();
  auto g = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.internal_forces());
  double error = 0.0, norm = 0.0;
  for (int n = 0; n < cells.num_nodes(); ++n) {
    const Eigen::Vector3d expected = q * Eigen::Vector3d(f(n, 0), f(n, 1), f(n, 2));
    error += (Eigen::Vector3d(g(n, 0), g(n, 1), g(n, 2)) - expected).squaredNorm();
    norm += expected.squaredNorm();
  }
  std::cout << "  rotated body: force error " << std::sqrt(error / norm) << ", energy change "
            << std::fabs(rotated_energy - energy) / energy << " (relative)\n";
  EXPECT_LT(std::sqrt(error / norm), 1e-12);
  EXPECT_NEAR(rotated_energy / energy, 1.0, 1e-12);
}

TEST(NeoHookeanForces, PassThePatchTest) {
  // A homogeneous deformation x = F X + c is an exact solution with no body force: the
  // interior nodes feel no net force, and every element carries the exact stress, so
  // the energy is V W(F).
  const CellMesh mesh = testing::tetrahedral_box(4, 2.0);
  Population cells(one_cell(mesh));
  std::mt19937 rng(13);
  const Eigen::Matrix3d f = random_deformation_gradient(rng, 0.3);
  deform(cells, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(f * x + Eigen::Vector3d(1, 2, 3)); });
  const double energy = cells.compute_internal_forces_and_energy();
  const double expected_energy = 8.0 * material.energy_density(to_mat3(f));
  auto force = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.internal_forces());
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.reference_positions());
  double interior = 0.0, boundary = 0.0;
  Eigen::Vector3d face_force = Eigen::Vector3d::Zero();
  for (int n = 0; n < cells.num_nodes(); ++n) {
    const Eigen::Vector3d fn(force(n, 0), force(n, 1), force(n, 2));
    bool on_surface = false;
    for (int i = 0; i < 3; ++i) on_surface |= std::fabs(std::fabs(x0(n, i)) - 1.0) < 1e-12;
    (on_surface ? boundary : interior) = std::max(on_surface ? boundary : interior, fn.norm());
    // Nodes strictly inside the face X = +1 (no edge or corner): their forces sum to
    // −P N A over their tributary area, (n−1)²/n² of the face (here 9/16 of 4 μm²).
    if (std::fabs(x0(n, 0) - 1.0) < 1e-12 && std::fabs(x0(n, 1)) < 1.0 - 1e-12 && std::fabs(x0(n, 2)) < 1.0 - 1e-12)
      face_force += fn;
  }
  const Eigen::Matrix3d p = reference_first_piola(f, material);
  const Eigen::Vector3d expected_face_force = -p * Eigen::Vector3d(1, 0, 0) * (4.0 * 9.0 / 16.0);
  std::cout << "  patch test: largest interior nodal force " << interior << " pN (boundary " << boundary
            << "), energy error " << std::fabs(energy / expected_energy - 1.0) << ", face traction error "
            << (face_force - expected_face_force).norm() / expected_face_force.norm() << "\n";
  EXPECT_LT(interior, 1e-12 * boundary);
  EXPECT_NEAR(energy / expected_energy, 1.0, 1e-12);
  EXPECT_LT((face_force - expected_face_force).norm(), 1e-12 * expected_face_force.norm());
}

TEST(NeoHookeanForces, ConserveMomentumAndAngularMomentum) {
  const CellMesh mesh = testing::tetrahedral_box(3, 3.0);
  Population cells(one_cell(mesh, {10.0, 4.0, -3.0}));
  deform_randomly(cells, 17, 0.15);
  cells.compute_internal_forces();
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.positions());
  auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.internal_forces());
  Eigen::Vector3d total = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double magnitude = 0.0, moment_magnitude = 0.0;
  for (int n = 0; n < cells.num_nodes(); ++n) {
    const Eigen::Vector3d fn(f(n, 0), f(n, 1), f(n, 2)), xn(x(n, 0), x(n, 1), x(n, 2));
    total += fn;
    moment += xn.cross(fn);
    magnitude += fn.norm();
    moment_magnitude += xn.norm() * fn.norm();
  }
  std::cout << "  Σ f = " << total.norm() << " pN (Σ|f| = " << magnitude << "), Σ x × f = " << moment.norm()
            << " pN·μm (Σ|x||f| = " << moment_magnitude << ")\n";
  EXPECT_LT(total.norm(), 1e-13 * magnitude);
  EXPECT_LT(moment.norm(), 1e-13 * moment_magnitude);
}

TEST(NeoHookeanForces, MatchAPlainSerialReference) {
  // The reference: per element F = D_s D_m⁻¹ with Eigen, P = F S from the S route,
  // f_a = −V0 P ∇N_a summed in a plain loop; the paper's law and with strain hardening.
  const CellMesh mesh = testing::tetrahedral_box(3, 3.0);
  for (const NeoHookeanMaterial& m : {material, mills_material, hardening_material}) {
    Population cells(one_cell(mesh, Eigen::Vector3d::Zero(), m));
    deform_randomly(cells, 19, 0.1);
    const double energy = cells.compute_internal_forces_and_energy();
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.positions());
    Kokkos::View<double* [3], Kokkos::HostSpace> expected("expected", cells.num_nodes());
    double expected_energy = 0.0;
    for (const auto& t : mesh.tetrahedra) {
      Eigen::Matrix3d dm, ds;
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) {
          dm(i, k) = mesh.nodes[t[k + 1]][i] - mesh.nodes[t[0]][i];
          ds(i, k) = x(t[k + 1], i) - x(t[0], i);
        }
      const Eigen::Matrix3d f = ds * dm.inverse();
      const Eigen::Matrix3d p = reference_first_piola(f, m);
      const double volume = dm.determinant() / 6.0;
      Eigen::Matrix<double, 3, 4> gradients;  // columns ∇N_a
      gradients.rightCols<3>() = dm.inverse().transpose();
      gradients.col(0) = -gradients.rightCols<3>().rowwise().sum();
      for (int a = 0; a < 4; ++a) {
        const Eigen::Vector3d fa = -volume * p * gradients.col(a);
        for (int i = 0; i < 3; ++i) expected(t[a], i) += fa[i];
      }
      expected_energy += volume * reference_energy_density(f, m);
    }
    auto computed = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.internal_forces());
    const double difference = testing::relativeDifference(flat(computed), flat(expected));
    std::cout << "  C3/G = " << m.c3 / shear_modulus << ": kernel vs serial reference: forces " << difference
              << ", energy " << std::fabs(energy / expected_energy - 1.0) << " (relative)\n";
    EXPECT_LT(difference, 1e-12);
    EXPECT_NEAR(energy / expected_energy, 1.0, 1e-12);
  }
}

#if defined(KOKKOS_ENABLE_SERIAL) && defined(KOKKOS_ENABLE_OPENMP) && !defined(KOKKOS_ENABLE_CUDA)
TEST(NeoHookeanForces, SerialAndThreadedRunsAgree) {
  const CellMesh mesh = testing::tetrahedral_box(6, 3.0);
  std::vector<PlacedCell> placed = one_cell(mesh);
  placed.push_back(placed[0]);
  placed[1].center = {4.0, 0.0, 0.0};
  BasicCellPopulation<Kokkos::Serial> serial(placed);
  BasicCellPopulation<Kokkos::OpenMP> threaded(placed);
  deform_randomly(serial, 23, 0.1);
  deform_randomly(threaded, 23, 0.1);
  const double serial_energy = serial.compute_internal_forces_and_energy();
  const double threaded_energy = threaded.compute_internal_forces_and_energy();
  const double difference =
      testing::relativeDifference(flat(threaded.internal_forces()), flat(serial.internal_forces()));
  std::cout << "  OpenMP (" << Kokkos::OpenMP().concurrency() << " threads) vs Serial: forces " << difference
            << ", energy " << std::fabs(threaded_energy / serial_energy - 1.0) << " (relative)\n";
  EXPECT_LT(difference, 1e-14);
  EXPECT_NEAR(threaded_energy / serial_energy, 1.0, 1e-14);
}
#endif

// ---- the global area and volume constraints of a cell (kernels/global_constraints.hpp)

const double area_modulus = 300.0;       // k_A [pN/μm]
const double volume_modulus = 40.0;      // k_V [Pa]
const NeoHookeanMaterial no_elasticity;  // zero moduli: the forces are the constraints' alone

// The serial reference: per triangle A_t = |(x1 − x0) × (x2 − x0)|/2,
// ∂A_t/∂x_k = ½ n̂ × (x_{k+2} − x_{k+1}), V_t = x0 · (x1 × x2)/6, ∂V_t/∂x_k = x_{k+1} × x_{k+2}/6;
// T = k_A (A − A0)/A0, P = k_V (V − V0)/V0, f = −T ∂A/∂x − P ∂V/∂x,
// E = k_A (A − A0)²/(2 A0) + k_V (V − V0)²/(2 V0), for the cell whose surface is `mesh`
// placed at `offset`.
struct ConstraintReference {
  double area = 0.0, volume = 0.0, energy = 0.0;
  std::vector<Eigen::Vector3d> forces;
};
template <class HostPositions>
ConstraintReference reference_constraint_forces(const CellMesh& mesh, const HostPositions& x, int offset,
                                                double k_a, double reference_area, double k_v,
                                                double reference_volume) {
  ConstraintReference r;
  r.forces.assign(mesh.nodes.size(), Eigen::Vector3d::Zero());
  std::vector<std::array<Eigen::Vector3d, 3>> area_gradients, volume_gradients;
  for (const auto& t : mesh.outer_surface) {
    Eigen::Vector3d y[3];
    for (int k = 0; k < 3; ++k) y[k] = Eigen::Vector3d(x(offset + t[k], 0), x(offset + t[k], 1), x(offset + t[k], 2));
    const Eigen::Vector3d normal = (y[1] - y[0]).cross(y[2] - y[0]);
    r.area += 0.5 * normal.norm();
    r.volume += y[0].dot(y[1].cross(y[2])) / 6.0;
    const Eigen::Vector3d unit = normal.normalized();
    std::array<Eigen::Vector3d, 3> ga, gv;
    for (int k = 0; k < 3; ++k) {
      ga[k] = 0.5 * unit.cross(y[(k + 2) % 3] - y[(k + 1) % 3]);
      gv[k] = y[(k + 1) % 3].cross(y[(k + 2) % 3]) / 6.0;
    }
    area_gradients.push_back(ga);
    volume_gradients.push_back(gv);
  }
  const double area_strain = (r.area - reference_area) / reference_area;
  const double volume_strain = (r.volume - reference_volume) / reference_volume;
  r.energy = 0.5 * k_a * reference_area * area_strain * area_strain +
             0.5 * k_v * reference_volume * volume_strain * volume_strain;
  for (std::size_t t = 0; t < mesh.outer_surface.size(); ++t)
    for (int k = 0; k < 3; ++k)
      r.forces[mesh.outer_surface[t][k]] -=
          k_a * area_strain * area_gradients[t][k] + k_v * volume_strain * volume_gradients[t][k];
  return r;
}

TEST(GlobalConstraints, VanishAtTheReferenceAndUnderRigidMotions) {
  // The box [−1.5, 1.5]³: A0 = 54 μm², V0 = 27 μm³. At rest, and moved rigidly, E = 0 and
  // no force, for the area and the volume constraint together.
  const CellMesh mesh = testing::tetrahedral_box(3, 3.0);
  Population cells(one_cell(mesh, {5.0, -2.0, 1.0}, no_elasticity, area_modulus, volume_modulus));
  ASSERT_TRUE(cells.has_global_constraints());
  const double a0 = host_copy(cells.reference_areas())(0), v0 = host_copy(cells.reference_volumes())(0);
  double worst_force = 0.0, worst_energy = 0.0, worst_tension = 0.0, worst_pressure = 0.0;
  for (const double angle : {0.0, 0.4, 2.5}) {
    const Eigen::Matrix3d r = rotation(angle, Eigen::Vector3d(1.0, -2.0, 0.5));
    const Eigen::Vector3d shift(3.0, 1.0, -7.0);
    if (angle > 0.0) deform(cells, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(r * x + shift); });
    const double energy = cells.compute_internal_forces_and_energy();
    const auto f = host_copy(cells.internal_forces());
    for (int n = 0; n < cells.num_nodes(); ++n)
      for (int i = 0; i < 3; ++i) worst_force = std::max(worst_force, std::fabs(f(n, i)));
    worst_energy = std::max(worst_energy, std::fabs(energy));
    worst_tension = std::max(worst_tension, std::fabs(host_copy(cells.area_tensions())(0)));
    worst_pressure = std::max(worst_pressure, std::fabs(host_copy(cells.volume_pressures())(0)));
    if (angle == 0.0) {
      EXPECT_EQ(energy, 0.0);
      EXPECT_EQ(worst_force, 0.0);
    }
  }
  // Scale: a 1 % area change gives T = 3 pN/μm and forces of T × 1 μm = 3 pN.
  std::cout << "  global constraints, k_A = " << area_modulus << " pN/um, A0 = " << a0 << " um^2, k_V = "
            << volume_modulus << " Pa, V0 = " << v0 << " um^3: at rest and moved rigidly, largest force "
            << worst_force << " pN, tension " << worst_tension << " pN/um, pressure " << worst_pressure
            << " Pa, energy " << worst_energy << " pN um\n";
  EXPECT_NEAR(a0, 54.0, 1e-12);
  EXPECT_NEAR(v0, 27.0, 1e-12);
  EXPECT_LT(worst_force, 1e-11 * area_modulus);
  EXPECT_LT(worst_tension, 1e-11 * area_modulus);
  EXPECT_LT(worst_pressure, 1e-11 * volume_modulus);
  EXPECT_LT(worst_energy, 1e-20 * area_modulus * a0);
  // Off (k_A = k_V = 0): not built, and the population says so.
  EXPECT_FALSE(Population(one_cell(mesh)).has_global_constraints());
  EXPECT_TRUE(Population(one_cell(mesh, Eigen::Vector3d::Zero(), material, 0.0, 1.0)).has_global_constraints());
  EXPECT_THROW(Population(one_cell(mesh, Eigen::Vector3d::Zero(), material, -1.0)), std::invalid_argument);
  EXPECT_THROW(Population(one_cell(mesh, Eigen::Vector3d::Zero(), material, 0.0, -1.0)), std::invalid_argument);
}

TEST(GlobalConstraints, ForcesAreMinusTheGradientOfTheEnergy) {
  // f = −∂E/∂x by central differences, each constraint alone, both, and with the elastic
  // forces; and the exact energy of a uniform dilation by s (the faces stay flat):
  // A = s² A0, V = s³ V0, E = k_A (s² − 1)² A0/2 + k_V (s³ − 1)² V0/2, T = k_A (s² − 1),
  // P = k_V (s³ − 1).
  const CellMesh mesh = testing::tetrahedral_box(3, 3.0);
  struct Variant {
    const char* name;
    NeoHookeanMaterial material;
    double k_a, k_v;
  };
  for (const Variant& v : {Variant{"area alone", no_elasticity, area_modulus, 0.0},
                           Variant{"volume alone", no_elasticity, 0.0, volume_modulus},
                           Variant{"area, volume and elastic", mills_material, area_modulus, volume_modulus}}) {
    Population cells(one_cell(mesh, Eigen::Vector3d::Zero(), v.material, v.k_a, v.k_v));
    deform_randomly(cells, 29, 0.08);
    cells.compute_internal_forces_and_energy();
    const double relative = force_vs_energy_gradient(cells);
    const CellMeasures measures = cells.measures()[0];
    std::cout << "  " << v.name << " (area " << std::showpos << 100.0 * (measures.area / 54.0 - 1.0) << " %, volume "
              << 100.0 * (measures.volume / 27.0 - 1.0) << std::noshowpos
              << " %): nodal force vs −∂E/∂x, relative error " << relative << "\n";
    EXPECT_LT(relative, 1e-6);
  }
  Population cells(one_cell(mesh, Eigen::Vector3d::Zero(), no_elasticity, area_modulus, volume_modulus));
  const double s = 1.1, a0 = 54.0, v0 = 27.0;
  deform(cells, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(s * x); });
  const double energy = cells.compute_internal_forces_and_energy();
  const double area_energy = 0.5 * area_modulus * (s * s - 1.0) * (s * s - 1.0) * a0;
  const double volume_energy = 0.5 * volume_modulus * (s * s * s - 1.0) * (s * s * s - 1.0) * v0;
  const double tension = host_copy(cells.area_tensions())(0), pressure = host_copy(cells.volume_pressures())(0);
  std::cout << "  uniform dilation by " << s << ": E " << energy << " pN um (exact " << area_energy + volume_energy
            << "), T " << tension << " pN/um (exact " << area_modulus * (s * s - 1.0) << "), P " << pressure
            << " Pa (exact " << volume_modulus * (s * s * s - 1.0) << ")\n";
  EXPECT_NEAR(energy / (area_energy + volume_energy), 1.0, 1e-12);
  EXPECT_NEAR(cells.constraint_energy() / (area_energy + volume_energy), 1.0, 1e-12);
  EXPECT_NEAR(tension / (area_modulus * (s * s - 1.0)), 1.0, 1e-12);
  EXPECT_NEAR(pressure / (volume_modulus * (s * s * s - 1.0)), 1.0, 1e-12);
}

TEST(GlobalConstraints, MatchAPlainSerialReferenceAndConserveMomentum) {
  // Two cells, the first with both constraints, the second without: the kernel's forces
  // against the serial reference, none on the second cell, and Σ f = 0, Σ x × f = 0.
  const CellMesh mesh = testing::tetrahedral_box(3, 3.0);
  std::vector<PlacedCell> placed = one_cell(mesh, {2.0, 1.0, -1.0}, no_elasticity, area_modulus, volume_modulus);
  placed.push_back(one_cell(mesh, {-4.0, 0.0, 0.0}, no_elasticity, 0.0)[0]);
  Population cells(placed);
  deform_randomly(cells, 31, 0.1);
  const double energy = cells.compute_internal_forces_and_energy();
  const auto x = host_copy(cells.positions());
  const auto f = host_copy(cells.internal_forces());
  const ConstraintReference expected = reference_constraint_forces(mesh, x, 0, area_modulus, 54.0, volume_modulus, 27.0);
  Kokkos::View<double* [3], Kokkos::HostSpace> expected_forces("expected", cells.num_nodes());
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    for (int i = 0; i < 3; ++i) expected_forces(n, i) = expected.forces[n][i];
  const double difference = testing::relativeDifference(flat(f), flat(expected_forces));
  double second_cell = 0.0, magnitude = 0.0, moment_magnitude = 0.0;
  Eigen::Vector3d total = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  for (int n = 0; n < cells.num_nodes(); ++n) {
    const Eigen::Vector3d fn(f(n, 0), f(n, 1), f(n, 2)), xn(x(n, 0), x(n, 1), x(n, 2));
    if (n >= static_cast<int>(mesh.nodes.size())) second_cell = std::max(second_cell, fn.norm());
    total += fn;
    moment += xn.cross(fn);
    magnitude += fn.norm();
    moment_magnitude += xn.norm() * fn.norm();
  }
  const std::vector<CellMeasures> measures = cells.measures();
  std::cout << "  global constraints vs serial reference: forces " << difference << ", energy "
            << std::fabs(energy / expected.energy - 1.0) << ", area " << measures[0].area << " (reference "
            << expected.area << ") um^2, volume " << measures[0].volume << " (reference " << expected.volume
            << ") um^3; second cell's largest force " << second_cell << " pN; Σ f = " << total.norm()
            << " pN, Σ x × f = " << moment.norm() << " pN um\n";
  EXPECT_LT(difference, 1e-12);
  EXPECT_NEAR(energy / expected.energy, 1.0, 1e-12);
  EXPECT_NEAR(measures[0].area / expected.area, 1.0, 1e-13);
  EXPECT_NEAR(measures[0].volume / expected.volume, 1.0, 1e-13);
  EXPECT_EQ(second_cell, 0.0);
  EXPECT_EQ(host_copy(cells.area_tensions())(1), 0.0);
  EXPECT_EQ(host_copy(cells.volume_pressures())(1), 0.0);
  EXPECT_LT(total.norm(), 1e-13 * magnitude);
  EXPECT_LT(moment.norm(), 1e-13 * moment_magnitude);
}

// ---- surface measures

TEST(CellMeasures, AreExactForABoxAnywhere) {
  // The box [−1.5, 1.5]³ has V = 27 μm³, A = 54 μm², centroid at its centre, wherever it
  // is placed and however it is rotated; the area weights add up to A.
  const CellMesh mesh = testing::tetrahedral_box(3, 3.0);
  std::vector<PlacedCell> placed = one_cell(mesh, {100.0, -50.0, 20.0});
  const Eigen::Matrix3d r = rotation(0.7, Eigen::Vector3d(1, 1, 0));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) placed[0].rotation[i][j] = r(i, j);
  placed.push_back(one_cell(mesh, {-3.0, 0.0, 0.0})[0]);
  Population cells(placed);
  const std::vector<CellMeasures> m = cells.measures();
  const auto node_weights = host_copy(cells.surface_area_weights());
  double weights = 0.0;
  for (int n = 0; n < cells.num_nodes(); ++n) weights += node_weights(n);
  std::cout << "  box: V " << m[0].volume << " A " << m[0].area << " centroid (" << m[0].centroid[0] << ", "
            << m[0].centroid[1] << ", " << m[0].centroid[2] << "); Σ w " << weights << "\n";
  ASSERT_EQ(m.size(), 2u);
  for (const CellMeasures& cell : m) {
    EXPECT_NEAR(cell.volume, 27.0, 1e-11);
    EXPECT_NEAR(cell.area, 54.0, 1e-11);
  }
  EXPECT_NEAR(m[0].centroid[0], 100.0, 1e-11);
  EXPECT_NEAR(m[0].centroid[1], -50.0, 1e-11);
  EXPECT_NEAR(m[0].centroid[2], 20.0, 1e-11);
  EXPECT_NEAR(m[1].centroid[0], -3.0, 1e-12);
  EXPECT_NEAR(weights, 2 * 54.0, 1e-10);
  // A homogeneous stretch F scales the volume by det F.
  const Eigen::Matrix3d f = Eigen::DiagonalMatrix<double, 3>(1.2, 0.9, 1.1);
  deform(cells, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(f * x); });
  EXPECT_NEAR(cells.measures()[1].volume, 27.0 * f.determinant(), 1e-11);
}

TEST(CellPopulation, RefusesInvertedElements) {
  CellMesh mesh = testing::tetrahedral_box(2, 2.0);
  std::swap(mesh.tetrahedra[3][1], mesh.tetrahedra[3][2]);
  EXPECT_THROW(Population{one_cell(mesh)}, std::invalid_argument);
}

}  // namespace
}  // namespace rouleau
