// The immersed coupling as a whole (src/coupling/immersed_coupling, src/run/simulation):
// a cell at rest stays at rest, a stiff sphere in simple shear turns at half the shear
// rate (the rigid-sphere value; Jeffery 1922) with the error falling under refinement,
// the power spread equals the power interpolated, and the scene with its skipped stages
// gives the full stage list's answer to round-off. The semi-implicit coupling's stiffness
// is the Hessian of the cells' energy: symmetric, linear, and its quadratic form the
// energy's second difference.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Kokkos_Core.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "capsule_expectations.hpp"
#include "sphere_in_shear.hpp"
#include "analysis/scene_checks.hpp"
#include "cells/cell_shape.hpp"
#include "config/load_case.hpp"
#include "coupling/cell_stiffness.hpp"
#include "run/simulation.hpp"
#include "temporary_folder.hpp"

namespace {

using rouleau::CaseConfig;
using rouleau::Simulation;

// A scratch folder per test (case files, mesh cache).
std::string scratch(const std::string& name) {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto folder = rouleau::testing::temporary_folder("coupling_" + std::string(test->name()));
  return (folder / name).string();
}

CaseConfig load_text(const std::string& text) {
  const std::string path = scratch("case.toml");
  std::ofstream(path) << text;
  return rouleau::load_case(path);
}

using rouleau::testing::host;
using rouleau::testing::HostVectors;
using rouleau::testing::shear_box;

TEST(Coupling, CellAtRestInQuiescentFluidStaysAtRest) {
  // A capsule (hollow sphere, denser than plasma) in fluid at rest between walls at rest,
  // no gravity: no force anywhere, so nothing may move.
  const CaseConfig config = load_text(shear_box(12.0, 8, 0.0) +
                                      "[time]\ndt_s = 1e-4\nend_s = 1e-3\n"
                                      "[cell_kinds.capsule]\nresolution = \"coarse\"\n"
                                      "[[cells]]\nkind = \"capsule\"\ncenter_um = [0.5, 0.3, 0.2]\n");
  Simulation simulation(config, scratch("meshes"));
  ASSERT_NE(simulation.coupling(), nullptr);
  EXPECT_TRUE(simulation.coupling()->runs_inertia());
  for (int step = 0; step < 5; ++step) simulation.advance();
  const auto& population = *simulation.cells().population;
  const auto x = host(population.positions()), x0 = host(population.reference_positions());
  const auto v = host(population.velocities());
  double largest_displacement = 0.0, largest_speed = 0.0;
  for (std::size_t n = 0; n < x.extent(0); ++n)
    for (int c = 0; c < 3; ++c) {
      largest_displacement = std::max(largest_displacement, std::fabs(x(n, c) - x0(n, c)));
      largest_speed = std::max(largest_speed, std::fabs(v(n, c)));
    }
  std::printf("cell at rest after 5 steps: largest displacement %.3g um, largest speed %.3g um/s\n",
              largest_displacement, largest_speed);
  EXPECT_LT(largest_displacement, 1e-12);
  EXPECT_LT(largest_speed, 1e-9);
  EXPECT_LT(simulation.fluid().kinetic_energy(), 1e-20);
}

TEST(Coupling, TaylorDeformationIsMeasuredOnTheMembraneMidSurface) {
  // A capsule shell (outer radius a = 2.82 μm, thickness h = 0.36 μm) placed so that its
  // mid-surface (radius a_m = a − h/2) becomes the ellipsoid a_m R diag(α, 1/α, 1) Rᵀ n
  // (R a turn by 30° about z) with the thickness kept along each node's radial direction
  // n: D = (α − 1/α) / (α + 1/α) and the inclination 30° exactly; the outer surface alone
  // would give (a_m α − a_m/α) / (a_m α + a_m/α + h), 0.014 lower.
  const CaseConfig config = load_text(shear_box(12.0, 4, 0.0) + "[time]\ndt_s = 1e-4\nend_s = 1e-3\n"
                                      "[cell_kinds.capsule]\nresolution = \"coarse\"\n"
                                      "[[cells]]\nkind = \"capsule\"\ncenter_um = [0, 0, 0]\n");
  Simulation simulation(config, scratch("meshes"));
  const auto& cells = simulation.cells();
  const double outer_radius = 2.82, thickness = 0.36, mid_radius = outer_radius - 0.5 * thickness;
  ASSERT_EQ(cells.membrane_depth, std::vector<double>{0.5 * thickness});
  const double stretch = 1.25, angle = 30.0 * M_PI / 180.0, c = std::cos(angle), s = std::sin(angle);
  const double m_xx = stretch * c * c + s * s / stretch, m_yy = stretch * s * s + c * c / stretch,
               m_xy = (stretch - 1.0 / stretch) * c * s;
  auto x = host(cells.population->reference_positions());
  for (std::size_t node = 0; node < x.extent(0); ++node) {
    const double r = std::hypot(x(node, 0), x(node, 1), x(node, 2));
    const double n[3] = {x(node, 0) / r, x(node, 1) / r, x(node, 2) / r};
    const double mid[3] = {mid_radius * (m_xx * n[0] + m_xy * n[1]), mid_radius * (m_xy * n[0] + m_yy * n[1]),
                           mid_radius * n[2]};
    for (int k = 0; k < 3; ++k) x(node, k) = mid[k] + (r - mid_radius) * n[k];
  }
  cells.population->set_positions(x);
  const auto measures = cells.population->measures();
  const auto shape = rouleau::shear_plane_shapes(*cells.population, measures, cells.membrane_depth).at(0);
  const auto outer = rouleau::shear_plane_shapes(*cells.population, measures).at(0);
  const double exact = (stretch - 1.0 / stretch) / (stretch + 1.0 / stretch);
  std::printf("mid-surface D %.4f, inclination %.2f deg (exact %.4f, 30 deg); outer-surface D %.4f\n",
              shape.taylor_deformation, shape.inclination_deg, exact, outer.taylor_deformation);
  // Tolerance: the nodes sample the tips at the coarse mesh's spacing (≈ 0.5 μm, an angle
  // of ≈ 0.1 rad, a relative distance error 1 − cos 0.1 ≈ 0.005 at most).
  EXPECT_NEAR(shape.taylor_deformation, exact, 0.005);
  EXPECT_NEAR(shape.length, mid_radius * stretch, 0.03);
  EXPECT_NEAR(shape.breadth, mid_radius / stretch, 0.03);
  EXPECT_NEAR(shape.inclination_deg, 30.0, 0.5);
  EXPECT_GT(shape.taylor_deformation - outer.taylor_deformation, 0.01);
  // The outer surface's extent: along z, unstretched, the outer diameter; along x, the
  // mid-surface ellipsoid's 2 a_m sqrt(m_xx² + m_xy²) plus at most the offset on each side.
  EXPECT_NEAR(shape.extent[2], 2.0 * outer_radius, 0.03);
  const double mid_extent_x = 2.0 * mid_radius * std::hypot(m_xx, m_xy);
  EXPECT_GT(shape.extent[0], mid_extent_x - 0.03);
  EXPECT_LT(shape.extent[0], mid_extent_x + thickness + 0.03);
  // Front and rear radii about the line along x through the centroid: the round shell has
  // both at its outer radius a; with the nodes behind x = −0.3 a pushed out from the axis
  // by 1.3 (a flared rear) the rear's is 1.3 a √(1 − 0.3²) = 1.24 a at most (less where no
  // node sits at x = −0.3 a), the front's about a (the flare moves the centroid off the
  // axis a little). Both equal a plain loop over the outer-surface nodes.
  auto flared = host(cells.population->reference_positions());
  cells.population->set_positions(flared);
  const auto round = rouleau::shear_plane_shapes(*cells.population, cells.population->measures()).at(0);
  for (std::size_t node = 0; node < flared.extent(0); ++node)
    if (flared(node, 0) < -0.3 * outer_radius)
      for (int k = 1; k < 3; ++k) flared(node, k) *= 1.3;
  cells.population->set_positions(flared);
  const auto flared_measures = cells.population->measures();
  const auto bell = rouleau::shear_plane_shapes(*cells.population, flared_measures).at(0);
  const auto weight =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.population->surface_area_weights());
  const auto& centre = flared_measures.at(0).centroid;
  double front = 0.0, rear = 0.0;
  for (std::size_t node = 0; node < flared.extent(0); ++node) {
    if (weight(node) <= 0.0) continue;
    const double r = std::hypot(flared(node, 1) - centre[1], flared(node, 2) - centre[2]);
    double& half = flared(node, 0) > centre[0] ? front : rear;
    half = std::max(half, r);
  }
  EXPECT_DOUBLE_EQ(bell.radius_front, front);
  EXPECT_DOUBLE_EQ(bell.radius_rear, rear);
  std::printf("round: front %.4f rear %.4f um; flared rear: front %.4f rear %.4f um (a = %.2f um)\n",
              round.radius_front, round.radius_rear, bell.radius_front, bell.radius_rear, outer_radius);
  EXPECT_NEAR(round.radius_front, outer_radius, 0.03);
  EXPECT_NEAR(round.radius_rear, outer_radius, 0.03);
  EXPECT_NEAR(bell.radius_front, outer_radius, 0.05);
  EXPECT_GT(bell.radius_rear / bell.radius_front, rouleau::CapillaryPassageCheck::flare_ratio);
  EXPECT_LT(bell.radius_rear, 1.3 * std::sqrt(1.0 - 0.09) * outer_radius + 0.03);
  EXPECT_GT(bell.radius_rear, 1.15 * outer_radius);
}

TEST(Coupling, CapsuleDeformsInProportionToCaAndKeepsItsVolume) {
  // The capsule case (thin shell, volume constraint) coarse, a/h_f = 2.7, to t = 0.02 s
  // (steady by then): in the small-deformation regime D ∝ Ca (Barthès-Biesel & Rallison
  // 1981: D → (25/4) Ca), so doubling Ca from 0.0125 doubles D, less the O(Ca²) term's
  // 3 % (the long tier's D / (25/4) Ca falls from 0.90 at Ca = 0.0125 to 0.82 at 0.05);
  // D stays below the limit (well below at this resolution: D converges from below as
  // a/h_f grows, docs/validation.md; the long tier checks the values); the enclosed volume is kept
  // within 1 %.
  const std::vector<std::string> coarse{"domain.elements=[18, 23, 18]", "time.dt_s=2e-4", "time.end_s=0.02"};
  const auto small = rouleau::testing::run_capsule(0.0125, coarse);
  const auto twice = rouleau::testing::run_capsule(0.025, coarse);
  const double ratio = twice.deformation / small.deformation;
  std::printf("coarse capsule: D(0.025) / D(0.0125) = %.4f (linear theory 2); D / (25/4 Ca) = %.3f, %.3f\n", ratio,
              small.deformation / (25.0 / 4.0 * 0.0125), twice.deformation / (25.0 / 4.0 * 0.025));
  EXPECT_NEAR(ratio, 2.0, 0.1);
  EXPECT_LT(twice.deformation, 25.0 / 4.0 * 0.025);
  rouleau::testing::expect_steady_and_volume_kept(small);
  rouleau::testing::expect_steady_and_volume_kept(twice);
}

TEST(Coupling, CapsuleWithoutTheConstraintKeepsItsVolumeWhenTheMembraneMovesWithTheWholeVelocity) {
  // The long tier's volume test reduced (CapsuleShearLong.VolumeKeptWithoutTheConstraint...):
  // the capsule case at a/h_f = 4.1, Ca = 0.05, without the volume constraint, to γ̇t = 5,
  // with the cells moving with u_h alone and with the settings that remove the membrane's
  // leak (the cells move with u_h + u', the loads enter the stabilization, RKPM support 2.5
  // elements). Threshold, set before the runs: the volume change at the end at most a
  // third of u_h's (at a/h_f = 4.1 over γ̇t = 10: +0.45 % against −2.26 %). Not at
  // a/h_f = 2.7: there these settings gain 1.52 % where the default loses 0.19 %
  // (measured; docs/validation.md).
  const std::vector<std::string> coarse{"domain.elements=[27, 34, 27]", "time.dt_s=1.3333e-4", "time.end_s=0.026",
                                        "cell_kinds.capsule.volume_modulus_Pa=0", "coupling.subscale_velocity=false"};
  std::vector<std::string> remedy = coarse;
  for (const char* setting : {"coupling.subscale_velocity=true", "coupling.forces_in_stabilization=true",
                              "coupling.support_elements=2.5"})
    remedy.push_back(setting);
  const auto before = rouleau::testing::run_capsule(0.05, coarse);
  const auto after = rouleau::testing::run_capsule(0.05, remedy);
  std::printf("capsule without the volume constraint at a/h_f = %.1f, gamma t = 5: volume change %+.3f %% (default), "
              "%+.3f %% (u_h + u', loads in the stabilization, support 2.5)\n",
              after.a_over_h, 100.0 * before.final_volume_change, 100.0 * after.final_volume_change);
  EXPECT_LT(std::fabs(after.final_volume_change), std::fabs(before.final_volume_change) / 3.0);
}

TEST(Coupling, StiffSphereInShearRotatesAtHalfTheShearRate) {
  // The stiff sphere of tests/sphere_in_shear.hpp between walls 8a apart (d = 4a: the
  // reference ω_z = −(γ̇/2)(1 − (5/8)/64) = −0.4951/s; its neglected terms, higher
  // reflections and the periodic images 8a apart, are ~0.1 %), at a/h = 1, 1.5 and 2.
  // Measured with u_h: errors of 0.19 %, 0.34 %, 0.09 % (0.13 % at a/h = 3): the reference's own
  // neglected terms and the coarse sphere mesh's facets; the test holds each below 0.5 %.
  // The long tier (long_sphere_shear) repeats it with walls 16a apart and a fine sphere
  // mesh, where the error falls with refinement to the reference's accuracy (2e-4).
  // With the default coupling (the sphere moves with u_h + u'): 0.19 %, 0.47 %, 0.09 %.
  for (const int n : {8, 12, 16}) {
    const auto r = rouleau::testing::run_sphere_in_shear(8.0, n, scratch(""));
    EXPECT_LT(r.error, 0.005);
    EXPECT_LT(std::fabs(r.centroid_y), 1e-3);  // stays at its height
    // Spreading is the transpose of interpolation: with the sphere moving with the
    // velocity the fluid solves for, u_h, the power it puts into the fluid, <u_h, S F>,
    // equals the power it takes back, <I u_h, F>, to round-off. (With u_h + u' the second
    // also holds <I u', F>, the work on the subscale velocity: 6-9e-2 pN um/s here.)
    const auto resolved = rouleau::testing::run_sphere_in_shear(8.0, n, scratch(""), "coarse", false);
    EXPECT_LT(resolved.error, 0.005);
    EXPECT_NEAR(resolved.power_spread, resolved.power_interpolated, 1e-12 * std::fabs(resolved.power_interpolated));
  }
}

TEST(Coupling, SkippedStagesChangeNothingButRoundOff) {
  // Two capsules as dense as the plasma, farther apart than the Morse cut-off, in shear:
  // the scene skips the Morse pair work (no pair in range), the inertia/buoyancy stage
  // (ρ_s = ρ_f), the RKPM correction (uniform mesh, cells off the walls) and list
  // rebuilds; the full stage list runs them all. The cells must end where they end with
  // the skips, to round-off.
  const std::string text = shear_box(24.0, 12, 4.0) +
                           "[time]\ndt_s = 2e-4\nend_s = 1\n"
                           "[cell_kinds.capsule]\nresolution = \"coarse\"\ndensity_kg_m3 = 1025\n"
                           "[[cells]]\nkind = \"capsule\"\ncenter_um = [-5.5, 1.0, 0]\n"
                           "[[cells]]\nkind = \"capsule\"\ncenter_um = [5.5, -1.0, 0]\n"
                           "[interaction]\nenabled = true\n"
                           // The Morse law's stable step (2e-5 s here) bounds cells in
                           // contact; these stay beyond the cut-off for the 8 steps.
                           "[coupling]\nallow_unstable_step = true\n";
  std::vector<HostVectors> positions;
  for (const bool skip : {true, false}) {
    const CaseConfig config = load_text(text + "[scene]\nskip_unneeded_stages = " + (skip ? "true" : "false") + "\n");
    Simulation simulation(config, scratch("meshes"));
    EXPECT_EQ(simulation.coupling()->runs_inertia(), !skip);
    for (int step = 0; step < 8; ++step) simulation.advance();
    EXPECT_EQ(simulation.last_report().corrected_points, skip ? 0 : simulation.cells().population->num_nodes());
    positions.push_back(host(simulation.cells().population->positions()));
  }
  const auto x0 = [&] {
    const CaseConfig config = load_text(text);
    return rouleau::make_case_cells(config, scratch("meshes")).population->reference_positions();
  }();
  const auto reference = host(x0);
  double largest_difference = 0.0, largest_displacement = 0.0;
  for (std::size_t n = 0; n < reference.extent(0); ++n)
    for (int c = 0; c < 3; ++c) {
      largest_difference = std::max(largest_difference, std::fabs(positions[0](n, c) - positions[1](n, c)));
      largest_displacement = std::max(largest_displacement, std::fabs(positions[0](n, c) - reference(n, c)));
    }
  std::printf("skipped vs full stage list after 8 steps: largest position difference %.3g um, largest "
              "displacement %.3g um\n", largest_difference, largest_displacement);
  EXPECT_GT(largest_displacement, 1e-4);  // the cells did move
  EXPECT_LT(largest_difference, 1e-10 * largest_displacement);
}

TEST(Coupling, SemiImplicitStiffnessIsTheSymmetricHessianOfTheCellsEnergy) {
  // Two capsules 0.4 um apart, each node moved at random by up to 0.02 um (a stressed
  // state), the Morse law in range. The stiffness operator of the semi-implicit coupling,
  // Ŝ u = −S K (Δt U I u) / (P L²) with K = ∂f/∂x, its elastic part by one-sided
  // differences and its Morse part exact (coupling/cell_stiffness.hpp), must be, for random
  // fluid velocities u, w:
  //   symmetric:  ⟨w, Ŝ u⟩ = ⟨u, Ŝ w⟩ (S = Iᵀ, K a Hessian);
  //   linear:     Ŝ (2u + 3w) = 2 Ŝ u + 3 Ŝ w;
  //   the energy's curvature: P L² Δt U ⟨u, Ŝ u⟩ = −⟨δx, K δx⟩ = d²E/ds² along δx = Δt U I u,
  //   E the elastic plus interaction energy, by a central second difference of E.
  // The elastic difference's truncation error is about h/ℓ ≈ 3e-6 (h = 1e-6 um, ℓ ≈ 0.3 um):
  // each is held to 1e-4. The second difference of E takes node displacements of 0.01 um:
  // its truncation error then falls as ε² (3e-5 here; 2e-4 at 0.03 um) while below about
  // 3e-3 um the round-off of E (2 pN um) takes over (3e-3 at 1e-3 um, 7e-2 at 1e-4 um);
  // it is held to 1e-3.
  const CaseConfig config = load_text(shear_box(16.0, 12, 0.0) +
                                      "[time]\ndt_s = 2e-5\nend_s = 1e-3\n"
                                      "[cell_kinds.capsule]\nresolution = \"coarse\"\n"
                                      "[[cells]]\nkind = \"capsule\"\ncenter_um = [-3.02, 0.1, 0]\n"
                                      "[[cells]]\nkind = \"capsule\"\ncenter_um = [3.02, -0.1, 0]\n"
                                      "[interaction]\nenabled = true\n");
  Simulation simulation(config, scratch("meshes"));
  rouleau::CellPopulation& population = *simulation.cells().population;
  rouleau::SurfaceInteraction& interaction = *simulation.cells().interaction;
  const int nodes = population.num_nodes();
  std::mt19937 random(20041);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  {
    auto x = host(population.positions());
    for (int n = 0; n < nodes; ++n)
      for (int c = 0; c < 3; ++c) x(n, c) += 0.02 * unit(random);
    population.set_positions(x);
  }
  rouleau::RkpmCoupler rkpm(simulation.mesh());
  rkpm.update(population.positions());
  using NodeVectors = rouleau::CellPopulation::NodeVectors;
  NodeVectors scratch_forces("scratch_forces", nodes);
  const rouleau::FluidScales scales = simulation.fluid().scales();
  rouleau::CellStiffness stiffness(
      nodes, rkpm,
      [&](const NodeVectors& positions, const NodeVectors& out) {
        rouleau::differenced_forces(population, nullptr, positions, scratch_forces, out);
      },
      &interaction, scales);
  const double dt = 2e-4;
  stiffness.linearize(population.positions(), dt);

  const int unknowns = simulation.fluid().fluid_operator().num_unknowns();
  using Vector = Kokkos::View<double*>;
  auto random_velocity = [&] {
    Vector v("velocity", unknowns);
    auto h = Kokkos::create_mirror_view(v);
    for (int i = 0; i < unknowns; ++i) h(i) = i % 4 == 3 ? 0.0 : unit(random);
    Kokkos::deep_copy(v, h);
    return v;
  };
  auto apply = [&](const Vector& v) {
    Vector y("stiffness_action", unknowns);
    stiffness.apply(v, y);
    return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), y);
  };
  auto dot = [&](const auto& a, const auto& b) {
    double sum = 0.0;
    for (int i = 0; i < unknowns; ++i) sum += a(i) * b(i);
    return sum;
  };
  const Vector u = random_velocity(), w = random_velocity();
  const auto u_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), u);
  const auto w_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), w);
  // 2u + 3w, formed on the host (a device lambda cannot live in a test body under CUDA).
  Vector combination("combination", unknowns);
  {
    auto c = Kokkos::create_mirror_view(combination);
    for (int i = 0; i < unknowns; ++i) c(i) = 2.0 * u_host(i) + 3.0 * w_host(i);
    Kokkos::deep_copy(combination, c);
  }
  const auto Su = apply(u), Sw = apply(w), Sc = apply(combination);

  const double uSu = dot(u_host, Su), wSw = dot(w_host, Sw);
  const double asymmetry = std::fabs(dot(w_host, Su) - dot(u_host, Sw)) / std::sqrt(std::fabs(uSu * wSw));
  double nonlinearity = 0.0, norm = 0.0;
  for (int i = 0; i < unknowns; ++i) {
    nonlinearity = std::max(nonlinearity, std::fabs(Sc(i) - 2.0 * Su(i) - 3.0 * Sw(i)));
    norm = std::max(norm, std::fabs(Sc(i)));
  }

  // d²E/ds² along δx = Δt U I u, by E(±ε) with ε max|δx| = 0.01 um.
  NodeVectors displacement("displacement", nodes);
  rkpm.interpolate(u, 4, displacement);
  auto delta = host(displacement);
  double largest = 0.0;
  for (int n = 0; n < nodes; ++n)
    for (int c = 0; c < 3; ++c) {
      delta(n, c) *= dt * scales.velocity;
      largest = std::max(largest, std::fabs(delta(n, c)));
    }
  const auto base = host(population.positions());
  auto energy_at = [&](double s) {
    auto x = host(population.positions());
    for (int n = 0; n < nodes; ++n)
      for (int c = 0; c < 3; ++c) x(n, c) = base(n, c) + s * delta(n, c);
    population.set_positions(x);
    const double energy = population.compute_internal_forces_and_energy() + interaction.compute_forces_and_energy();
    population.set_positions(base);
    return energy;
  };
  const double epsilon = 1e-2 / largest;
  const double curvature = (energy_at(epsilon) - 2.0 * energy_at(0.0) + energy_at(-epsilon)) / (epsilon * epsilon);
  const double quadratic_form = scales.force() * dt * scales.velocity * uSu;
  std::printf("semi-implicit stiffness: asymmetry %.2e, nonlinearity %.2e, <u,Su> P L^2 dt U = %.6e pN um vs "
              "d2E/ds2 = %.6e pN um (relative difference %.2e), %ld force evaluations\n",
              asymmetry, nonlinearity / norm, quadratic_form, curvature,
              std::fabs(quadratic_form - curvature) / std::fabs(curvature), stiffness.evaluations());
  EXPECT_LT(asymmetry, 1e-4);
  EXPECT_LT(nonlinearity, 1e-4 * norm);
  EXPECT_NEAR(quadratic_form, curvature, 1e-3 * std::fabs(curvature));
  EXPECT_EQ(stiffness.evaluations(), 4);  // one linearization, three actions
}

}  // namespace
