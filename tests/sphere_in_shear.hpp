#pragma once
// A stiff sphere in simple shear for the tests (tests/test_coupling.cpp with walls 8 radii
// apart, tests/long_sphere_shear.cpp with 16): a filled neo-Hookean sphere of radius
// a = 2 μm, G = 50 Pa (Ca = μγ̇/G = 2.4e-5 at γ̇ = 1/s: rigid for the purpose), centred
// between the walls of a cube periodic in x and z. A free rigid sphere in unbounded simple
// shear turns at ω_z = −γ̇/2 (Jeffery 1922); a wall at distance d slows it by (5/16)(a/d)³
// to leading order (Goldman, Cox & Brenner 1967), so two walls at d = H/2 give the
// reference ω_z = −(γ̇/2)(1 − (5/8)(2a/H)³). Run 30 steps of μ/(2G) (15 relaxation times
// μ/G of the solid) and fit ω to the nodes' velocities.
#include <Kokkos_Core.hpp>
#include <array>
#include <cmath>
#include <fstream>
#include <string>

#include "config/load_case.hpp"
#include "run/simulation.hpp"

namespace rouleau::testing {

// A cube of side `side` μm centred on the origin, `n` elements per side, periodic in x and
// z, walls at y = ±side/2 moving at ±wall_speed along x (simple shear, γ̇ = 2 wall_speed / side).
inline std::string shear_box(double side, int n, double wall_speed) {
  const std::string h = std::to_string(side / 2);
  const std::string v = std::to_string(wall_speed);
  return "[domain]\nlower_um = [-" + h + ", -" + h + ", -" + h + "]\nupper_um = [" + h + ", " + h + ", " + h +
         "]\nelements = [" + std::to_string(n) + ", " + std::to_string(n) + ", " + std::to_string(n) +
         "]\n[boundary.x_min]\ntype = \"periodic\"\n[boundary.x_max]\ntype = \"periodic\"\n"
         "[boundary.z_min]\ntype = \"periodic\"\n[boundary.z_max]\ntype = \"periodic\"\n"
         "[boundary.y_min]\ntype = \"wall\"\nvelocity_um_s = [-" + v + ", 0, 0]\n"
         "[boundary.y_max]\ntype = \"wall\"\nvelocity_um_s = [" + v + ", 0, 0]\n";
}

// Host copies of a (node, 3) View.
using HostVectors = Kokkos::View<double* [3], Kokkos::HostSpace>;
inline HostVectors host(const CellPopulation::ConstNodeVectors& v) {
  HostVectors h("host", v.extent(0));
  Kokkos::deep_copy(h, v);
  return h;
}

// The angular velocity about z of the cell's nodes, fitted to rigid rotation about the
// centroid: ω_z = Σ (r_x v_y − r_y v_x) / Σ (r_x² + r_y²).
inline double angular_velocity_z(const CellPopulation& population, const std::array<double, 3>& centroid) {
  const auto x = host(population.positions()), v = host(population.velocities());
  double moment = 0.0, inertia = 0.0;
  for (std::size_t n = 0; n < x.extent(0); ++n) {
    const double rx = x(n, 0) - centroid[0], ry = x(n, 1) - centroid[1];
    moment += rx * v(n, 1) - ry * v(n, 0);
    inertia += rx * rx + ry * ry;
  }
  return moment / inertia;
}

struct SphereInShear {
  double a_over_h = 0.0;
  double omega = 0.0;      // fitted ω_z [1/s]
  double expected = 0.0;   // the wall-corrected reference [1/s]
  double error = 0.0;      // |ω / expected − 1|
  double centroid_y = 0.0;  // [μm]
  double power_spread = 0.0, power_interpolated = 0.0;  // [pN·μm/s]
};

// The sphere between walls `walls_apart` radii apart (the cube's side), `n` elements per
// side, its mesh at `resolution` (a preset); the case file and the mesh cache go into
// `folder`. With `subscale_velocity` false the sphere moves with u_h alone instead of the
// default u_h + u' (coupling.subscale_velocity).
inline SphereInShear run_sphere_in_shear(double walls_apart, int n, const std::string& folder,
                                         const std::string& resolution = "coarse", bool subscale_velocity = true) {
  const double radius = 2.0, shear_rate = 1.0, side = walls_apart * radius;
  const std::string path = folder + "/sphere_in_shear.toml";
  std::ofstream(path) << shear_box(side, n, 0.5 * side * shear_rate)
                      << "[time]\ndt_s = 1.2e-5\nend_s = 1\n"
                         "[cell_kinds.ball]\nshape = \"sphere\"\nbody = \"filled\"\ndiameter_um = 4.0\n"
                         "shear_modulus_Pa = 50.0\nresolution = \"" << resolution << "\"\n"
                         "[[cells]]\nkind = \"ball\"\ncenter_um = [0, 0, 0]\n"
                         "[coupling]\nsubscale_velocity = " << (subscale_velocity ? "true" : "false") << "\n";
  Simulation simulation(load_case(path), folder + "/meshes");
  for (int step = 0; step < 30; ++step) simulation.advance();
  const auto& population = *simulation.cells().population;
  const auto measures = population.measures();
  SphereInShear result;
  result.a_over_h = radius * n / side;
  result.omega = angular_velocity_z(population, measures[0].centroid);
  result.expected = -0.5 * shear_rate * (1.0 - 5.0 / 8.0 * std::pow(2.0 / walls_apart, 3));
  result.error = std::fabs(result.omega / result.expected - 1.0);
  result.centroid_y = measures[0].centroid[1];
  result.power_spread = simulation.last_report().power_spread;
  result.power_interpolated = simulation.last_report().power_interpolated;
  std::printf("sphere in shear, walls %.0fa apart, a/h = %.2f: omega_z = %.6f /s (reference %.6f), relative error "
              "%.2e; centroid y %.2e um; power spread %.6e, interpolated %.6e pN um/s\n",
              walls_apart, result.a_over_h, result.omega, result.expected, result.error, result.centroid_y,
              result.power_spread, result.power_interpolated);
  return result;
}

}  // namespace rouleau::testing
