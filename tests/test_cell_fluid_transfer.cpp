// The cells' transfer to and from the fluid with hollow shells coupled at their
// mid-surface (coupling/cell_fluid_transfer.hpp, kernels/shell_midsurface.hpp): the
// mid-surface points against a plain serial reference and against the sphere's exact
// mid-surface, the transfer's adjointness ⟨I u, F⟩ = ⟨u, S F⟩, and the velocity it gives in
// a linear flow: the flow's own at the nodes except the normal part of a shell node's,
// taken at its mid-surface point (so a rigid rotation is reproduced exactly).
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "config/cell_kinds.hpp"
#include "config/load_case.hpp"
#include "coupling/cell_fluid_transfer.hpp"
#include "run/simulation.hpp"
#include "sphere_in_shear.hpp"  // shear_box, host
#include "temporary_folder.hpp"

namespace {

using rouleau::CellFluidTransfer;
using rouleau::testing::host;
using rouleau::testing::HostVectors;
using Vector = Kokkos::View<double*>;

// A capsule (hollow sphere, radius R = 2.82 μm, shell h = 0.36 μm) at `capsule_center`
// and a filled ball beside it, in a 16 μm box of 12³ hexahedra, with the mid-surface
// coupling on.
constexpr std::array<double, 3> capsule_center{-1.9, 0.3, 0.1};
constexpr double capsule_radius = 0.5 * rouleau::capsule_diameter;
constexpr double shell_thickness = 0.36;

struct TwoCells {
  std::string folder;
  rouleau::CaseConfig config;
  std::unique_ptr<rouleau::Simulation> simulation;
};

TwoCells two_cells() {
  TwoCells scene;
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  scene.folder = rouleau::testing::temporary_folder("transfer_" + std::string(test->name())).string();
  const std::string path = scene.folder + "/case.toml";
  std::ofstream(path) << rouleau::testing::shear_box(16.0, 12, 0.0)
                      << "[time]\ndt_s = 1e-4\nend_s = 1e-3\n"
                         "[coupling]\nshell_midsurface = true\n"
                         "[cell_kinds.capsule]\nresolution = \"coarse\"\n"
                         "[cell_kinds.ball]\nshape = \"sphere\"\nbody = \"filled\"\ndiameter_um = 2.0\n"
                         "resolution = \"coarse\"\n"
                         "[[cells]]\nkind = \"capsule\"\ncenter_um = [-1.9, 0.3, 0.1]\n"
                         "[[cells]]\nkind = \"ball\"\ncenter_um = [2.6, -0.2, 0.0]\n";
  scene.config = rouleau::load_case(path);
  scene.simulation = std::make_unique<rouleau::Simulation>(scene.config, scene.folder + "/meshes");
  return scene;
}

// The serial reference of the mid-surface points: n_I summed over both surfaces'
// triangles of the capsule (the population's first cell), p_I = x_I − (h/2) n_I / |n_I|.
HostVectors reference_midsurface_points(const TwoCells& scene) {
  const auto& cells = scene.simulation->cells();
  const auto x = host(cells.population->positions());
  HostVectors normal("normal", x.extent(0)), points("points", x.extent(0));
  const rouleau::CellMesh& mesh = cells.meshes.at("capsule");
  for (const auto* surface : {&mesh.outer_surface, &mesh.inner_surface})
    for (const auto& t : *surface) {
      double e1[3], e2[3];
      for (int i = 0; i < 3; ++i) {
        e1[i] = x(t[1], i) - x(t[0], i);
        e2[i] = x(t[2], i) - x(t[0], i);
      }
      const double a[3] = {0.5 * (e1[1] * e2[2] - e1[2] * e2[1]), 0.5 * (e1[2] * e2[0] - e1[0] * e2[2]),
                           0.5 * (e1[0] * e2[1] - e1[1] * e2[0])};
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) normal(t[k], i) += a[i];
    }
  for (std::size_t n = 0; n < x.extent(0); ++n) {
    const double length = std::sqrt(normal(n, 0) * normal(n, 0) + normal(n, 1) * normal(n, 1) +
                                     normal(n, 2) * normal(n, 2));
    for (int i = 0; i < 3; ++i)
      points(n, i) = x(n, i) - (length > 0.0 ? 0.5 * shell_thickness * normal(n, i) / length : 0.0);
  }
  return points;
}

TEST(CellFluidTransfer, ShellNodesMeetTheFluidOnTheirMembranesMidSurface) {
  // Against the serial reference, to round-off; and on the sphere's exact mid-surface,
  // |p − c| = R − h/2, from both the outer surface (at R) and the cavity wall (at R − h),
  // to the faceting error of the node normals. The filled ball's nodes stay where they are.
  const TwoCells scene = two_cells();
  const auto& cells = scene.simulation->cells();
  CellFluidTransfer transfer(scene.simulation->mesh(), 2.0, cells, scene.config, true);
  transfer.update(cells.population->positions());
  const auto points = host(transfer.midsurface_points());
  const auto x = host(cells.population->positions());
  const HostVectors reference = reference_midsurface_points(scene);
  const int capsule_nodes = static_cast<int>(cells.meshes.at("capsule").nodes.size());
  double largest_difference = 0.0, largest_radius_error = 0.0, largest_ball_shift = 0.0;
  for (std::size_t n = 0; n < x.extent(0); ++n) {
    double radius2 = 0.0, shift2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      largest_difference = std::max(largest_difference, std::fabs(points(n, i) - reference(n, i)));
      radius2 += std::pow(points(n, i) - capsule_center[i], 2);
      shift2 += std::pow(points(n, i) - x(n, i), 2);
    }
    if (static_cast<int>(n) < capsule_nodes)
      largest_radius_error =
          std::max(largest_radius_error, std::fabs(std::sqrt(radius2) - (capsule_radius - 0.5 * shell_thickness)));
    else
      largest_ball_shift = std::max(largest_ball_shift, std::sqrt(shift2));
  }
  std::printf("mid-surface points: largest difference from the serial reference %.3g um; largest error of |p - c| "
              "against R - h/2 = %.4f um: %.3g um (%.2g of h)\n",
              largest_difference, capsule_radius - 0.5 * shell_thickness, largest_radius_error,
              largest_radius_error / shell_thickness);
  EXPECT_LT(largest_difference, 1e-12);
  EXPECT_LT(largest_radius_error, 0.05 * shell_thickness);
  EXPECT_EQ(largest_ball_shift, 0.0);
}

TEST(CellFluidTransfer, SpreadingIsTheExactTransposeOfInterpolationWithMidSurfacePoints) {
  // ⟨I u, F⟩ = ⟨u, S F⟩ for random u on the fluid's unknowns and random F on the nodes.
  const TwoCells scene = two_cells();
  const auto& cells = scene.simulation->cells();
  CellFluidTransfer transfer(scene.simulation->mesh(), 2.0, cells, scene.config, true);
  transfer.update(cells.population->positions());
  const int nodes = cells.population->num_nodes();
  const int unknowns = scene.simulation->mesh().num_unknowns();
  std::mt19937 random(2004);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Vector u("u", unknowns), spread("spread", unknowns);
  auto u_host = Kokkos::create_mirror_view(u);
  for (int i = 0; i < unknowns; ++i) u_host(i) = unit(random);
  Kokkos::deep_copy(u, u_host);
  CellFluidTransfer::NodeVectors forces("forces", nodes), interpolated("interpolated", nodes);
  HostVectors forces_host("forces", nodes);
  for (int n = 0; n < nodes; ++n)
    for (int i = 0; i < 3; ++i) forces_host(n, i) = unit(random);
  Kokkos::deep_copy(forces, forces_host);
  transfer.interpolate(u, 4, interpolated);
  transfer.spread(forces, spread, 4);
  const auto v = host(interpolated);
  auto s = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), spread);
  double on_cells = 0.0, on_fluid = 0.0, scale = 0.0;
  for (int n = 0; n < nodes; ++n)
    for (int i = 0; i < 3; ++i) {
      on_cells += v(n, i) * forces_host(n, i);
      scale += std::fabs(v(n, i) * forces_host(n, i));
    }
  for (int i = 0; i < unknowns; ++i) on_fluid += u_host(i) * s(i);
  std::printf("<I u, F> = %.15g, <u, S F> = %.15g, relative difference %.3g\n", on_cells, on_fluid,
              std::fabs(on_cells - on_fluid) / scale);
  EXPECT_LT(std::fabs(on_cells - on_fluid), 1e-13 * scale);
}

TEST(CellFluidTransfer, LinearFlowGivesShellNodesTheNormalVelocityOfTheirMidSurface) {
  // u(x) = A x + b, which the RKPM window reproduces exactly. A shell node must get
  //   v_I = A x_I + b − (h/2) (n̂·A n̂) n̂,
  // a filled body's node A x_I + b. With A a rotation (antisymmetric) the correction
  // vanishes: the capsule turns rigidly. With a strain (symmetric) it is the layer's
  // thickness rate that is taken away: (h/2) n̂·A n̂ at each surface.
  const TwoCells scene = two_cells();
  const auto& cells = scene.simulation->cells();
  CellFluidTransfer transfer(scene.simulation->mesh(), 2.0, cells, scene.config, true);
  transfer.update(cells.population->positions());
  const auto normals = host(transfer.shell_normals());
  const auto x = host(cells.population->positions());
  const rouleau::FluidMesh& mesh = scene.simulation->mesh();
  const auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const int nodes = cells.population->num_nodes();
  const double b[3] = {0.3, -0.2, 0.1};
  const double rotation[3][3] = {{0, -2.0, 0.5}, {2.0, 0, -1.0}, {-0.5, 1.0, 0}};
  const double strain[3][3] = {{1.0, 0.4, 0.0}, {0.4, -0.3, 0.2}, {0.0, 0.2, -0.7}};
  for (const auto* A : {&rotation, &strain}) {
    Vector u("u", mesh.num_unknowns());
    auto u_host = Kokkos::create_mirror_view(u);
    for (int node = 0; node < mesh.num_nodes; ++node)
      for (int i = 0; i < 3; ++i) {
        double value = b[i];
        for (int j = 0; j < 3; ++j) value += (*A)[i][j] * coordinates(node, j);
        u_host(4 * mesh.dof_node_of_node[node] + i) = value;
      }
    Kokkos::deep_copy(u, u_host);
    CellFluidTransfer::NodeVectors interpolated("interpolated", nodes);
    transfer.interpolate(u, 4, interpolated);
    const auto v = host(interpolated);
    double largest_error = 0.0, largest_correction = 0.0;
    for (int n = 0; n < nodes; ++n) {
      double normal_strain = 0.0;  // n̂·A n̂
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) normal_strain += normals(n, i) * (*A)[i][j] * normals(n, j);
      for (int i = 0; i < 3; ++i) {
        double expected = b[i] - 0.5 * shell_thickness * normal_strain * normals(n, i);
        for (int j = 0; j < 3; ++j) expected += (*A)[i][j] * x(n, j);
        largest_error = std::max(largest_error, std::fabs(v(n, i) - expected));
        largest_correction = std::max(largest_correction, std::fabs(0.5 * shell_thickness * normal_strain));
      }
    }
    std::printf("%s: largest error %.3g um/s, largest normal correction (h/2) n.A.n %.3g um/s\n",
                A == &rotation ? "rotation" : "strain", largest_error, largest_correction);
    EXPECT_LT(largest_error, 1e-11);
    if (A == &rotation) EXPECT_LT(largest_correction, 1e-14);
    else EXPECT_GT(largest_correction, 0.1);  // the strain's correction is there to see
  }
}

}  // namespace
