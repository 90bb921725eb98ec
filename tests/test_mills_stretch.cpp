// The optical-tweezers stretch of one red blood cell (Mills, Qie, Dao, Lim & Suresh 2004,
// Mech. Chem. Biosystems 1, 169) as a static solve of the solid alone (docs/method.md,
// "Static stretch"): a hollow Evans–Fung shell (h = 0.36 μm, the paper's mesh resolution:
// 1238 nodes, 3767 tetrahedra) pulled by a force F spread as a uniform traction over the
// outer-surface nodes within a 2 μm contact patch at each end of a diameter (x), along the
// line through the patches' centres (src/cells/static_equilibrium.hpp).
//
// Diameters as Mills et al. measured them on the images: axial = the largest extent along
// the pull, transverse = the largest extent across it in the plane of the disc (y).
//
// Mills et al. 2004 (healthy cells, their figure of diameters against force, mean and
// error bar), as digitised in the RBC-stretch data of the Korali/Mirheo examples
// (Mills.2004.txt): force [pN], axial mean [lower, upper], transverse mean [lower, upper]
// [μm]. The error bars are used as they are, not widened.
//
// Two membranes:
//
// 1. The paper's law, the "normal" kind (G_s = 4.2 pN/μm, ν = 0.45, no strain hardening,
//    no area constraint): MillsStretch.PaperMembraneAgainstMillsEtAl2004. Inside the bars
//    at 0 and 16 pN (the axial diameter at 16 pN only just: 9.99 μm, bar up to 9.995), the
//    transverse diameter inside at every force, but the axial one too long from 38 pN up:
//    12.9 μm at 38 pN (bar up to 12.1), 18.0 at 68 pN (13.8), ~55 at 193 pN (17.7). The
//    3D neo-Hookean shell is strain-softening and area-extensible (small-strain area
//    modulus K_A = G_s (1+ν)/(1−ν) ≈ 2.6 G_s): its area grows by 33 % at 68 pN and 150 %
//    at 193 pN, while Mills' axial × transverse products (60, 61, 65 μm²) show a cell that
//    keeps its area. Neither the mesh (coarse / paper / fine: 18.8 / 18.0 / 18.0 μm at
//    68 pN), the load patch, G_s (4.2–16 pN/μm), ν (0.45–0.49) nor the enclosed volume
//    held changes that (DISABLED_MillsStretch.ParameterStudy).
//
// 2. The "Mills membrane" kind, the paper's law with the two options a cell kind may
//    switch on, as a case file gives it:
//
//      [cell_kinds.mills]
//      membrane_shear_modulus_pN_um = 5.3   # G_s, Mills et al.'s fitted value
//      poisson_ratio = 0.45
//      strain_hardening_ratio = 0.0333333   # C3 = G/30, Mills et al.'s hardening term
//      area_modulus_pN_um = 1000            # k_A, the global area constraint
//
//    plus the enclosed volume held (the incompressible cytoplasm, which the coupled model
//    gets from the fluid; here the static solve's augmented-Lagrangian constraint).
//    Mills et al. fitted W = (μ0/2)(I1 − 3) + C3 (I1 − 3)³ with C3 = μ0/30 and a membrane
//    shear modulus of 5.3 pN/μm to these data (an incompressible shell); here the same
//    hardening acts on the isochoric J1 (kernels/neo_hookean.hpp). k_A = 1000 pN/μm keeps
//    the area within 2 % at 193 pN (+1.4 %), and a stiffer k_A changes little: k_A = 3000
//    (+0.5 %) gives 16.55 μm axial at 193 pN against 16.77 μm here, k_A = 300 (+3.7 %)
//    17.25 μm. It is far below the membrane's local dilation modulus (5e5 pN/μm,
//    the paper's): a global term keeps the total area with a much smaller modulus.
//    MillsStretch.MillsMembraneInsideMillsErrorBars: inside every bar from 0 to 193 pN.
//    Both options are needed: without the hardening the axial diameter is 22.8 μm at
//    193 pN; without the area constraint it is 14.1 μm at 68 pN (bar up to 13.8) and
//    19.9 μm at 193 pN. Holding the volume matters less (17.4 μm at 193 pN without it,
//    still inside, the volume then 19 % down).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Kokkos_Core.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "cells/cell_population.hpp"
#include "cells/cells_from_case.hpp"
#include "cells/static_equilibrium.hpp"
#include "cells/stretch_patches.hpp"
#include "config/cell_kinds.hpp"
#include "config/load_case.hpp"
#include "geometry/cell_mesh.hpp"
#include "mills_stretch.hpp"

namespace rouleau {
namespace {

using namespace rouleau::testing;

bool inside(double value, double lower, double upper) { return value >= lower && value <= upper; }

void print(const StretchResult& r) {
  const MillsPoint& m = mills_point_near(r.force);
  std::printf(
      "  Mills stretch %3.0f pN: axial %5.2f um (Mills %5.2f, bar %5.2f-%5.2f) %s, transverse %4.2f um (Mills %4.2f, "
      "bar %4.2f-%4.2f) %s; area %+.2f %%, volume %+.2f %%, largest J1-3 %.2f; %s after %d iterations (%d force "
      "evaluations), residual %.2g pN (tolerance %.2g), %.2f s\n",
      r.force, r.diameters.axial, m.axial, m.axial_lower, m.axial_upper,
      inside(r.diameters.axial, m.axial_lower, m.axial_upper) ? "inside" : "OUTSIDE", r.diameters.transverse,
      m.transverse, m.transverse_lower, m.transverse_upper,
      inside(r.diameters.transverse, m.transverse_lower, m.transverse_upper) ? "inside" : "OUTSIDE",
      100.0 * (r.area / r.reference_area - 1.0), 100.0 * (r.volume / r.reference_volume - 1.0), r.distortion,
      r.report.converged ? "converged" : r.report.stop_reason.c_str(), r.report.iterations, r.report.force_evaluations,
      r.report.max_residual, r.report.tolerance, r.report.seconds);
  std::fflush(stdout);
}

// Host copy of a View (node, 3) as Eigen points.
std::vector<Eigen::Vector3d> host_points(const Kokkos::View<const double* [3]>& view) {
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  std::vector<Eigen::Vector3d> points(h.extent(0));
  for (std::size_t a = 0; a < h.extent(0); ++a) points[a] = Eigen::Vector3d(h(a, 0), h(a, 1), h(a, 2));
  return points;
}

// The largest distance between corresponding points after the best rigid alignment of
// `moved` onto `reference` (Kabsch: translation of the centroids, rotation from the SVD of
// the covariance).
double distance_after_rigid_alignment(const std::vector<Eigen::Vector3d>& moved,
                                      const std::vector<Eigen::Vector3d>& reference) {
  Eigen::Vector3d cm = Eigen::Vector3d::Zero(), cr = Eigen::Vector3d::Zero();
  for (std::size_t a = 0; a < moved.size(); ++a) {
    cm += moved[a];
    cr += reference[a];
  }
  cm /= moved.size();
  cr /= moved.size();
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (std::size_t a = 0; a < moved.size(); ++a) h += (moved[a] - cm) * (reference[a] - cr).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
  double largest = 0.0;
  for (std::size_t a = 0; a < moved.size(); ++a)
    largest = std::max(largest, (r * (moved[a] - cm) + cr - reference[a]).norm());
  return largest;
}

// ---- tests

TEST(MillsStretch, PatchesHoldAFewPercentOfTheSurfaceNodesAtEachEnd) {
  StretchSetup setup;
  const StretchPatches& patches = *setup.patches;
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), patches.signed_weights());
  double positive = 0.0, negative = 0.0;
  for (std::size_t a = 0; a < w.extent(0); ++a) (w(a) > 0 ? positive : negative) += w(a);
  const int surface = patches.cell_surface_nodes();
  std::printf(
      "  contact patches (d_c = %.1f um): %d and %d of %d outer-surface nodes (%.1f %%, %.1f %%), areas %.2f "
      "and %.2f um^2 (a flat disc of d_c: %.2f um^2); weights sum to %+.15f and %+.15f\n",
      contact_diameter, patches.node_count(1), patches.node_count(-1), surface, 100.0 * patches.node_count(1) / surface,
      100.0 * patches.node_count(-1) / surface, patches.patch_area(1), patches.patch_area(-1),
      M_PI * 0.25 * contact_diameter * contact_diameter, positive, negative);
  for (const int side : {1, -1}) {
    EXPECT_GE(patches.node_count(side), 0.01 * surface);
    EXPECT_LE(patches.node_count(side), 0.05 * surface);
  }
  EXPECT_NEAR(positive, 1.0, 1e-12);
  EXPECT_NEAR(negative, -1.0, 1e-12);
}

TEST(MillsStretch, ZeroForceKeepsTheReferenceShape) {
  // (a) Unloaded and at rest in the reference configuration: already in equilibrium, not
  // one node moves.
  {
    StretchSetup setup;
    setup.solver->set_pull(setup.patches->signed_weights(), 0.0);
    const StaticEquilibriumReport report = setup.solver->solve();
    const auto x = host_points(setup.cells->positions()), x0 = host_points(setup.cells->reference_positions());
    double moved = 0.0;
    for (std::size_t a = 0; a < x.size(); ++a) moved = std::max(moved, (x[a] - x0[a]).norm());
    const StretchDiameters d = setup.patches->diameters(*setup.cells);
    std::printf(
        "  0 pN from rest: %s after %d iterations, residual %.2g pN, largest move %.2g um, diameters %.3f x "
        "%.3f um\n",
        report.stop_reason.c_str(), report.iterations, report.max_residual, moved, d.axial, d.transverse);
    EXPECT_TRUE(report.converged);
    EXPECT_EQ(report.iterations, 0);
    EXPECT_EQ(moved, 0.0);
    EXPECT_NEAR(d.axial, normal_kind().diameter, 0.05);  // nodes on the rim of the faceted mesh
    EXPECT_NEAR(d.transverse, normal_kind().diameter, 0.05);
  }
  // (b) Unloaded but started from a distorted shape (10 % longer along x, 5 % thinner along
  // y, nodes jittered by up to 0.02 μm): relaxes back to the reference shape, up to a rigid
  // motion, and its mass-weighted centroid does not move (no rigid mode is excited).
  {
    StretchSetup setup;
    const auto x0 = host_points(setup.cells->reference_positions());
    std::mt19937 rng(2004);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    auto start = Kokkos::create_mirror_view(setup.cells->positions());
    for (std::size_t a = 0; a < x0.size(); ++a) {
      start(a, 0) = 1.10 * x0[a].x() + jitter(rng);
      start(a, 1) = 0.95 * x0[a].y() + jitter(rng);
      start(a, 2) = x0[a].z() + jitter(rng);
    }
    setup.cells->set_positions(start);
    auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), setup.solver->fictitious_masses());
    auto centroid = [&](const std::vector<Eigen::Vector3d>& x) {
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      double m = 0.0;
      for (std::size_t a = 0; a < x.size(); ++a) {
        c += mass(a) * x[a];
        m += mass(a);
      }
      return Eigen::Vector3d(c / m);
    };
    const Eigen::Vector3d centroid_before = centroid(host_points(setup.cells->positions()));
    const double distortion = distance_after_rigid_alignment(host_points(setup.cells->positions()), x0);
    const StaticEquilibriumReport report = setup.solver->solve();
    const auto x = host_points(setup.cells->positions());
    const double distance = distance_after_rigid_alignment(x, x0);
    const double drift = (centroid(x) - centroid_before).norm();
    std::printf(
        "  0 pN from a distorted shape (%.3f um off): %s after %d iterations (%.2f s), residual %.2g pN; "
        "%.2g um off the reference shape after rigid alignment, centroid moved %.2g um\n",
        distortion, report.stop_reason.c_str(), report.iterations, report.seconds, report.max_residual, distance,
        drift);
    EXPECT_TRUE(report.converged);
    EXPECT_LT(distance, 1e-3);
    EXPECT_LT(drift, 1e-10);
  }
}

TEST(MillsStretch, SolverReachesATrueEquilibrium) {
  // At 68 pN: the solver's own residual, then an independent check from the population's
  // internal forces and the patch weights on the host: r_a = f_int,a + F w_a p̂,
  // max_a |r_a| ≤ 1e-5 F; the applied loads balance (Σ f_ext = 0, Σ (x − c) × f_ext = 0);
  // and a tenfold tighter tolerance moves the diameters by less than 0.01 μm. With the
  // strain-hardening and area-constrained law (the Mills membrane without the volume held:
  // its internal forces are then all the forces), whose stiff global area mode the solver
  // must cope with.
  const double force = 68.0;
  Membrane membrane = mills_membrane;
  membrane.volume_held = false;
  StretchSetup setup(membrane);
  setup.solver->set_pull(setup.patches->signed_weights(), force);
  const StaticEquilibriumReport report = setup.solver->solve();
  ASSERT_TRUE(report.converged) << report.stop_reason;
  const StretchDiameters d = setup.patches->diameters(*setup.cells);

  setup.cells->compute_internal_forces();
  const auto x = host_points(setup.cells->positions());
  const auto f = host_points(setup.cells->internal_forces());
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), setup.patches->signed_weights());
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), c = Eigen::Vector3d::Zero();
  for (std::size_t a = 0; a < x.size(); ++a) {
    p += w(a) * x[a];
    c += x[a];
  }
  c /= x.size();
  const Eigen::Vector3d pull = force * p.normalized();
  double largest = 0.0;
  Eigen::Vector3d total_load = Eigen::Vector3d::Zero(), load_moment = Eigen::Vector3d::Zero();
  for (std::size_t a = 0; a < x.size(); ++a) {
    const Eigen::Vector3d load = w(a) * pull;
    largest = std::max(largest, (f[a] + load).norm());
    total_load += load;
    load_moment += (x[a] - c).cross(load);
  }
  StaticEquilibriumOptions tighter;
  tighter.relative_tolerance = 1e-6;
  const StaticEquilibriumReport tight = setup.solver->solve(tighter);
  const StretchDiameters dt = setup.patches->diameters(*setup.cells);
  std::printf(
      "  68 pN, hardening and area constraint: %d iterations, %d force evaluations, %.2f s; residual %.3g pN "
      "(solver) / %.3g pN (host), tolerance %.3g pN; sum of loads %.2g pN, their moment %.2g pN um; tolerance 1e-6 (%d more "
      "iterations): axial %.4f -> %.4f um, transverse %.4f -> %.4f um\n",
      report.iterations, report.force_evaluations, report.seconds, report.max_residual, largest, report.tolerance,
      total_load.norm(), load_moment.norm(), tight.iterations, d.axial, dt.axial, d.transverse, dt.transverse);
  EXPECT_LE(report.max_residual, 1e-5 * force);
  EXPECT_LE(largest, 1e-5 * force * (1.0 + 1e-9));
  EXPECT_LT(total_load.norm(), 1e-12 * force);
  EXPECT_LT(load_moment.norm(), 1e-10 * force);
  EXPECT_TRUE(tight.converged);
  EXPECT_LT(std::fabs(dt.axial - d.axial), 0.01);
  EXPECT_LT(std::fabs(dt.transverse - d.transverse), 0.01);
}

TEST(MillsStretch, VolumeConstraintHoldsTheEnclosedVolume) {
  // The optional incompressible-cytoplasm constraint: at 68 pN the free shell loses about
  // 12 % of its volume; held, the volume stays within 1e-4 of V0 by a positive (inflating)
  // pressure, and the solve is still a true equilibrium (pressure forces included). The
  // soft penalty (k = 1 pN/μm⁵: 6e-4 off after the first relaxation) makes the augmented
  // Lagrangian update its multiplier.
  StretchSetup setup;
  const double v0 = setup.cells->measures()[0].volume;
  setup.solver->set_pull(setup.patches->signed_weights(), 68.0);
  setup.solver->set_volume_constraint(1.0);
  const StaticEquilibriumReport report = setup.solver->solve();
  const double v = setup.cells->measures()[0].volume;
  const double residual = setup.solver->compute_residual();
  const double pressure = setup.solver->cell_pressures()[0];
  std::printf(
      "  68 pN, volume held: %s, %d iterations, %d multiplier updates, %.2f s; V %.3f -> %.3f um^3 "
      "(%.1e), pressure %.4f Pa, residual %.2g pN (tolerance %.2g)\n",
      report.stop_reason.c_str(), report.iterations, report.volume_updates, report.seconds, v0, v,
      std::fabs(v / v0 - 1.0), pressure, residual, report.tolerance);
  EXPECT_TRUE(report.converged);
  EXPECT_GE(report.volume_updates, 1);
  EXPECT_LE(std::fabs(v / v0 - 1.0), 1e-4);
  EXPECT_GT(pressure, 0.0);
  EXPECT_LE(residual, report.tolerance * (1.0 + 1e-9));
}

TEST(MillsStretch, PaperMembraneAgainstMillsEtAl2004) {
  // The paper's law (the "normal" kind) at Mills' forces: every solve converges; inside the
  // bars at 0 and 16 pN; the transverse diameter inside at every force; the axial one too
  // long from 38 pN up (see the head of this file); the axial diameter grows and the
  // transverse one shrinks with the force.
  std::vector<StretchResult> results;
  for (const double force : {0.0, 16.0, 38.0, 68.0, 130.0, 193.0}) {
    results.push_back(stretch(force));
    print(results.back());
    EXPECT_TRUE(results.back().report.converged) << force << " pN: " << results.back().report.stop_reason;
  }
  for (std::size_t k = 0; k < results.size(); ++k) {
    const StretchResult& r = results[k];
    const MillsPoint& m = mills_point_near(r.force);
    EXPECT_TRUE(inside(r.diameters.transverse, m.transverse_lower, m.transverse_upper)) << r.force << " pN";
    if (r.force <= 16.0)
      EXPECT_TRUE(inside(r.diameters.axial, m.axial_lower, m.axial_upper)) << r.force << " pN";
    else
      EXPECT_GT(r.diameters.axial, m.axial_upper) << r.force << " pN";
    if (k > 0) {
      EXPECT_GT(r.diameters.axial, results[k - 1].diameters.axial);
      EXPECT_LT(r.diameters.transverse, results[k - 1].diameters.transverse);
    }
  }
  std::printf("  paper membrane at 16 pN: axial %.4f um, %.4f um below the top of Mills' bar\n",
              results[1].diameters.axial, mills_point_near(16.0).axial_upper - results[1].diameters.axial);
}

TEST(MillsStretch, MillsMembraneKindFromACaseFile) {
  // The Mills membrane given as a case file's kind (the head of this file) reaches the
  // cells as the law the next test checks: the cell make_case_cells places has the same
  // elastic and area energy, stretched by diag(1.3, 0.85, 1), as the test's own (and not
  // the energy without the hardening or without the area term).
  const CaseConfig config = load_case(std::string(ROULEAU_TEST_DATA_DIR) + "/good_case.toml",
                                      mills_membrane_case_overrides());
  const CellKindConfig& kind = config.cell_kinds.back();
  const std::filesystem::path cache =
      std::filesystem::temp_directory_path() / ("rouleau-test-mills-" + std::to_string(::getpid()));
  const CaseCells from_case = make_case_cells(config, cache.string());
  std::filesystem::remove_all(cache);
  ASSERT_TRUE(from_case.population);
  ASSERT_EQ(from_case.population->num_nodes(), static_cast<int>(normal_mesh().nodes.size()));
  // E at x = c + S (X − c), c the cell's centre (a copy of X: a host mirror would alias it).
  const auto stretched_energy = [](CellPopulation& cells, const std::array<double, 3>& center) {
    auto x = Kokkos::create_mirror(Kokkos::HostSpace(), cells.reference_positions());
    Kokkos::deep_copy(x, cells.reference_positions());
    const double s[3] = {1.6, 0.7, 1.0};
    for (std::size_t a = 0; a < x.extent(0); ++a)
      for (int i = 0; i < 3; ++i) x(a, i) = center[i] + s[i] * (x(a, i) - center[i]);
    cells.set_positions(x);
    return cells.compute_internal_forces_and_energy();
  };
  const double energy = stretched_energy(*from_case.population, config.cells[0].center);
  const double area_energy = from_case.population->constraint_energy();
  const std::array<double, 3> origin{0.0, 0.0, 0.0};
  CellPopulation expected(std::vector<PlacedCell>{placed_cell(mills_membrane)});
  const double expected_energy = stretched_energy(expected, origin);
  Membrane other = mills_membrane;
  other.strain_hardening_ratio = 0.0;
  CellPopulation without_hardening(std::vector<PlacedCell>{placed_cell(other)});
  const double energy_without_hardening = stretched_energy(without_hardening, origin);
  other = mills_membrane;
  other.area_modulus = 0.0;
  CellPopulation without_area(std::vector<PlacedCell>{placed_cell(other)});
  const double energy_without_area = stretched_energy(without_area, origin);
  const double g = kind.shear_modulus;
  std::printf(
      "  Mills membrane kind: G %.4f Pa (G_s %.3f pN/um), K %.3f Pa, C3/G %.5f, k_A %.0f pN/um; stretched by "
      "diag(1.6, 0.7, 1): E %.3f pN um (area term %.3f; the test's own cell %.3f, without hardening %.3f, without "
      "the area term %.3f)\n",
      g, g * kind.shell_thickness, kind.bulk_modulus, kind.strain_hardening_ratio, kind.area_modulus, energy,
      area_energy, expected_energy, energy_without_hardening, energy_without_area);
  EXPECT_EQ(kind.name, "mills");
  EXPECT_NEAR(energy / expected_energy, 1.0, 1e-12);
  EXPECT_GT(std::fabs(energy_without_hardening / energy - 1.0), 1e-3);
  EXPECT_GT(area_energy, 1e-2 * energy);
  EXPECT_NEAR(energy_without_area + area_energy, energy, 1e-12 * energy);
}

TEST(MillsStretch, MillsMembraneInsideMillsErrorBars) {
  // The Mills membrane (the head of this file) at Mills' forces: every solve converges and
  // both diameters lie inside Mills' error bars from 0 to 193 pN; the area changes by less
  // than 2 % and the enclosed volume by less than 1e-4.
  for (const double force : {0.0, 16.0, 38.0, 68.0, 130.0, 193.0}) {
    const StretchResult r = stretch(force, mills_membrane);
    print(r);
    const MillsPoint& m = mills_point_near(force);
    EXPECT_TRUE(r.report.converged) << force << " pN: " << r.report.stop_reason;
    EXPECT_TRUE(inside(r.diameters.axial, m.axial_lower, m.axial_upper))
        << force << " pN: axial " << r.diameters.axial << " um, Mills " << m.axial_lower << "-" << m.axial_upper;
    EXPECT_TRUE(inside(r.diameters.transverse, m.transverse_lower, m.transverse_upper))
        << force << " pN: transverse " << r.diameters.transverse << " um, Mills " << m.transverse_lower << "-"
        << m.transverse_upper;
    EXPECT_LT(std::fabs(r.area / r.reference_area - 1.0), 0.02) << force << " pN";
    EXPECT_LT(std::fabs(r.volume / r.reference_volume - 1.0), 1e-4) << force << " pN";
  }
}

// The evidence behind the head of this file: membrane shear modulus (the paper's 4.2, the
// 5.3 Mills et al. fitted, stiffer), Poisson ratio (0.45–0.49), the enclosed
// volume held, and the Mills membrane's ingredients one at a time (strain hardening, area
// constraint and its modulus, volume), at 68 and 193 pN.
// About 17 s on one core: run with --gtest_also_run_disabled_tests.
TEST(MillsStretch, DISABLED_ParameterStudy) {
  const std::vector<Membrane> membranes = {
      {4.2, 0.45, 0.0, 0.0, false},        {4.2, 0.49, 0.0, 0.0, false},       {4.2, 0.45, 0.0, 0.0, true},
      {5.3, 0.45, 0.0, 0.0, false},        {8.0, 0.45, 0.0, 0.0, false},       {12.0, 0.45, 0.0, 0.0, false},
      {12.0, 0.49, 0.0, 0.0, false},       {16.0, 0.45, 0.0, 0.0, false},      {5.3, 0.45, 1.0 / 30.0, 0.0, true},
      {5.3, 0.45, 0.0, 1000.0, true},      {5.3, 0.45, 1.0 / 30.0, 1000.0, false},
      {5.3, 0.45, 1.0 / 30.0, 300.0, true}, {5.3, 0.45, 1.0 / 30.0, 3000.0, true}, mills_membrane,
  };
  for (const Membrane& membrane : membranes) {
    std::printf("  G_s = %.1f pN/um, nu = %.2f, C3/G = %.4f, k_A = %.0f pN/um%s:\n", membrane.shear_modulus,
                membrane.poisson_ratio, membrane.strain_hardening_ratio, membrane.area_modulus,
                membrane.volume_held ? ", enclosed volume held" : "");
    for (const double force : {68.0, 193.0}) print(stretch(force, membrane));
  }
}

}  // namespace
}  // namespace rouleau
