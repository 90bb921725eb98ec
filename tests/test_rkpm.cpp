// RKPM interpolation and spreading (paper eqs. 15, 16): exact reproduction of constant
// and linear fields anywhere (next to walls, on graded meshes, across periodic sides),
// partition of unity, adjointness ⟨I u, F⟩ = ⟨u, S F⟩, and the skipped correction agreeing
// with the computed one where the plain window already reproduces linear fields; the
// shape functions, interpolation and spreading against plain serial references.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <iostream>
#include <random>
#include <set>

#include "coupling/rkpm_coupler.hpp"
#include "mesh/fluid_mesh.hpp"
#include "vessel_profiles.hpp"

namespace rouleau {
namespace {

template <class View>
auto host_copy(const View& v) {
  auto copy = Kokkos::create_mirror(Kokkos::HostSpace(), v);
  Kokkos::deep_copy(copy, v);
  return copy;
}

// Random points in the box [lower + margin, upper − margin].
RkpmCoupler::PointVectors random_points(const FluidMesh& mesh, int count, double margin, std::uint32_t seed) {
  std::mt19937 rng(seed);
  RkpmCoupler::PointVectors points("points", count);
  auto h = Kokkos::create_mirror_view(points);
  for (int p = 0; p < count; ++p)
    for (int d = 0; d < 3; ++d) {
      std::uniform_real_distribution<double> u(mesh.lower[d] + margin, mesh.upper[d] - margin);
      h(p, d) = u(rng);
    }
  Kokkos::deep_copy(points, h);
  return points;
}

// Nodal values (stride 4) of the field f at the dof nodes' positions.
template <class Field>
Kokkos::View<double*> nodal_field(const FluidMesh& mesh, const Field& f) {
  Kokkos::View<double*> nodal("nodal", 4 * mesh.num_dof_nodes);
  auto h = Kokkos::create_mirror_view(nodal);
  auto x = host_copy(mesh.coordinates);
  for (int n = 0; n < mesh.num_nodes; ++n) {
    const auto value = f(x(n, 0), x(n, 1), x(n, 2));
    for (int c = 0; c < 3; ++c) h(4 * mesh.dof_node_of_node[n] + c) = value[c];
  }
  Kokkos::deep_copy(nodal, h);
  return nodal;
}

// The largest |I f − f| over the points for a field f (3 components).
template <class Field>
double interpolation_error(const FluidMesh& mesh, const RkpmCoupler& coupler, const RkpmCoupler::PointVectors& points,
                           const Field& f) {
  const auto nodal = nodal_field(mesh, f);
  RkpmCoupler::PointVectors values("values", points.extent(0));
  coupler.interpolate(nodal, 4, values);
  const auto v = host_copy(values);
  const auto x = host_copy(points);
  double worst = 0.0;
  for (std::size_t p = 0; p < x.extent(0); ++p) {
    const auto exact = f(x(p, 0), x(p, 1), x(p, 2));
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(v(p, c) - exact[c]));
  }
  return worst;
}

TEST(Rkpm, ReproducesConstantAndLinearFieldsNextToWallsAndOnGradedMeshes) {
  // Walls everywhere, graded 3:1 toward them; points anywhere up to the walls.
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {20, 10, 10}, {10, 6, 6}, {3, 3, 1}, {false, false, false});
  RkpmCoupler coupler(mesh);
  const auto points = random_points(mesh, 500, 0.0, 1);
  coupler.update(points);
  const double constant = interpolation_error(mesh, coupler, points, [](double, double, double) {
    return std::array<double, 3>{1.0, -2.0, 3.5};
  });
  const double linear = interpolation_error(mesh, coupler, points, [](double x, double y, double z) {
    return std::array<double, 3>{1.0 + 0.3 * x - 0.2 * y + 0.7 * z, -2.0 + y, 0.5 * z - 0.1 * x};
  });
  std::cout << "  graded walled box: " << coupler.corrected_points() << " of 500 points corrected; largest error "
            << constant << " (constant), " << linear << " (linear, values up to ~15)\n";
  EXPECT_LT(constant, 1e-12);
  EXPECT_LT(linear, 1e-11);
  EXPECT_EQ(coupler.corrected_points(), 500);  // a graded mesh needs it everywhere
}

TEST(Rkpm, UniformPeriodicBoxNeedsNoCorrectionAwayFromWalls) {
  // Periodic in x and z, walls at y = 0, 10: the window alone reproduces linear fields
  // more than a support away from the walls, and the correction, forced there, changes
  // the shape functions only by round-off.
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {20, 10, 10}, {10, 5, 5}, {1, 1, 1}, {true, false, true});
  RkpmCoupler coupler(mesh);
  // y in [4.5, 5.5]: more than 2 h = 4 μm from both walls.
  auto points = random_points(mesh, 300, 0.0, 2);
  {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points);
    for (std::size_t p = 0; p < h.extent(0); ++p) h(p, 1) = 4.5 + h(p, 1) / 10.0;
    Kokkos::deep_copy(points, h);
  }
  coupler.update(points);
  const int corrected = coupler.corrected_points();
  const auto plain = host_copy(coupler.shape_functions());
  const auto offsets = host_copy(coupler.offsets());
  coupler.always_correct(true);
  coupler.update(points);
  const auto corrected_phi = host_copy(coupler.shape_functions());
  double worst = 0.0;
  for (int k = 0; k < offsets(300); ++k) worst = std::max(worst, std::fabs(plain(k) - corrected_phi(k)));
  // Linear in y (the non-periodic direction) and constant: reproduced across the
  // periodic sides too.
  const double linear = interpolation_error(mesh, coupler, points, [](double, double y, double) {
    return std::array<double, 3>{2.0 * y, 1.0, -y};
  });
  std::cout << "  uniform periodic box: " << corrected << " of 300 interior points needed the correction; plain vs "
            << "corrected shape functions differ by " << worst << "; linear error " << linear << "\n";
  EXPECT_EQ(corrected, 0);
  EXPECT_LT(worst, 1e-13);
  EXPECT_LT(linear, 1e-12);
}

TEST(Rkpm, PartitionOfUnityAndAdjointness) {
  // Σ_J Φ_J = 1 at every point; ⟨I u, F⟩ = ⟨u, S F⟩ for random u and F; so the total
  // force spread equals the total force on the points.
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {20, 10, 10}, {8, 6, 6}, {1, 2, 1}, {true, false, true});
  RkpmCoupler coupler(mesh);
  const auto points = random_points(mesh, 400, 0.0, 3);
  coupler.update(points);
  const auto offsets = host_copy(coupler.offsets());
  const auto phi = host_copy(coupler.shape_functions());
  double worst_sum = 0.0;
  for (int p = 0; p < 400; ++p) {
    double sum = 0.0;
    for (int k = offsets(p); k < offsets(p + 1); ++k) sum += phi(k);
    worst_sum = std::max(worst_sum, std::fabs(sum - 1.0));
  }
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Kokkos::View<double*> nodal("u", 4 * mesh.num_dof_nodes);
  RkpmCoupler::PointVectors forces("F", 400), values("Iu", 400);
  auto hn = Kokkos::create_mirror_view(nodal);
  auto hf = Kokkos::create_mirror_view(forces);
  for (std::size_t i = 0; i < hn.extent(0); ++i) hn(i) = u(rng);
  for (int p = 0; p < 400; ++p)
    for (int c = 0; c < 3; ++c) hf(p, c) = u(rng);
  Kokkos::deep_copy(nodal, hn);
  Kokkos::deep_copy(forces, hf);
  coupler.interpolate(nodal, 4, values);
  Kokkos::View<double*> spread("SF", 4 * mesh.num_dof_nodes);
  coupler.spread(forces, spread, 4);
  const auto iu = host_copy(values);
  const auto sf = host_copy(spread);
  double left = 0.0, right = 0.0, magnitude = 0.0;
  double total_points[3] = {0, 0, 0}, total_nodes[3] = {0, 0, 0};
  for (int p = 0; p < 400; ++p)
    for (int c = 0; c < 3; ++c) {
      left += iu(p, c) * hf(p, c);
      magnitude += std::fabs(iu(p, c) * hf(p, c));
      total_points[c] += hf(p, c);
    }
  for (int n = 0; n < mesh.num_dof_nodes; ++n)
    for (int c = 0; c < 3; ++c) {
      right += hn(4 * n + c) * sf(4 * n + c);
      total_nodes[c] += sf(4 * n + c);
    }
  double total_difference = 0.0;
  for (int c = 0; c < 3; ++c) total_difference = std::max(total_difference, std::fabs(total_points[c] - total_nodes[c]));
  std::cout << "  partition of unity: largest |Σ Φ − 1| " << worst_sum << "; <Iu, F> − <u, SF> = " << left - right
            << " (Σ|terms| " << magnitude << "); total force spread vs on points: " << total_difference << "\n";
  EXPECT_LT(worst_sum, 1e-13);
  EXPECT_LT(std::fabs(left - right), 1e-13 * magnitude);
  EXPECT_LT(total_difference, 1e-12);
}

TEST(Rkpm, SupportNodesAreEveryNodeOfTheRowsOnce) {
  // Serial reference: the set of the CSR rows' nodes, ascending. Points gathered in one
  // corner, so that most nodes are in no support.
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {20, 10, 10}, {8, 6, 6}, {1, 2, 1}, {true, false, true});
  RkpmCoupler coupler(mesh);
  RkpmCoupler::PointVectors points("points", 50);
  auto hp = Kokkos::create_mirror_view(points);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.5, 4.0);
  for (int p = 0; p < 50; ++p)
    for (int c = 0; c < 3; ++c) hp(p, c) = u(rng);
  Kokkos::deep_copy(points, hp);
  coupler.update(points);
  const auto offsets = host_copy(coupler.offsets());
  const auto nodes = host_copy(coupler.nodes());
  std::set<int> expected;
  for (int k = 0; k < offsets(50); ++k) expected.insert(nodes(k));
  const auto support = host_copy(coupler.support_nodes());
  std::vector<int> found(support.data(), support.data() + support.extent(0));
  EXPECT_EQ(found, std::vector<int>(expected.begin(), expected.end()));
  EXPECT_LT(found.size(), static_cast<std::size_t>(mesh.num_dof_nodes) / 2) << "the points fill the box";
}

TEST(Rkpm, RestrictedRowsAreTheFullRowsOfTheActivePointsAndEmptyElsewhere) {
  // restrict_rows (a rank's own and ghost cells): against the rows of every
  // point, the active points' rows are the same nodes and shape functions bit for bit,
  // the others are empty (interpolation gives them zero, spreading takes nothing from
  // them), and a point outside the fluid is refused only when it is active.
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {8, 6, 6}, {8, 6, 6}, {1, 1.3, 1}, {true, false, true});
  const RkpmCoupler::PointVectors points = random_points(mesh, 40, 0.2, 17);
  RkpmCoupler every(mesh), some(mesh);
  every.update(points);
  Kokkos::View<int*> active("active", 40);
  auto ha = Kokkos::create_mirror_view(active);
  for (int p = 0; p < 40; ++p) ha(p) = p % 3 == 1;
  Kokkos::deep_copy(active, ha);
  some.restrict_rows(active);
  some.update(points);
  const auto full_offsets = host_copy(every.offsets()), offsets = host_copy(some.offsets());
  const auto full_nodes = host_copy(every.nodes()), nodes = host_copy(some.nodes());
  const auto full_phi = host_copy(every.shape_functions()), phi = host_copy(some.shape_functions());
  int mismatches = 0;
  for (int p = 0; p < 40; ++p) {
    const int count = offsets(p + 1) - offsets(p);
    if (!ha(p)) {
      mismatches += count != 0;
      continue;
    }
    mismatches += count != full_offsets(p + 1) - full_offsets(p);
    for (int k = 0; k < count && k < full_offsets(p + 1) - full_offsets(p); ++k)
      mismatches += nodes(offsets(p) + k) != full_nodes(full_offsets(p) + k) ||
                    phi(offsets(p) + k) != full_phi(full_offsets(p) + k);
  }
  EXPECT_EQ(mismatches, 0);
  // A field linear across the walls (and constant along the periodic directions): the
  // active points get it, the others zero.
  const auto field = [](double, double y, double) { return std::array<double, 3>{1 + 0.5 * y, 2 - y, 3.0}; };
  RkpmCoupler::PointVectors values("values", 40);
  some.interpolate(nodal_field(mesh, field), 4, values);
  const auto v = host_copy(values), x = host_copy(points);
  double worst = 0.0;
  for (int p = 0; p < 40; ++p) {
    const auto exact = field(x(p, 0), x(p, 1), x(p, 2));
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(v(p, c) - (ha(p) ? exact[c] : 0.0)));
  }
  EXPECT_LT(worst, 1e-12);
  // An inactive point outside the fluid is not refused; an active one is.
  auto hx = Kokkos::create_mirror_view(points);
  Kokkos::deep_copy(hx, points);
  hx(0, 1) = -50.0;  // point 0 is inactive
  Kokkos::deep_copy(points, hx);
  EXPECT_NO_THROW(some.update(points));
  hx(1, 1) = -50.0;  // point 1 is active
  Kokkos::deep_copy(points, hx);
  EXPECT_THROW(some.update(points), PointsOutsideFluidError);
}

TEST(Rkpm, ReproducesLinearFieldsNextToTheCurvedWallOfAVessel) {
  // A Gmsh contraction (3 → 1.5 μm) of tetrahedra: the supports are truncated by the
  // curved wall and the node spacing is irregular everywhere, so the correction runs at
  // every point; it must reproduce linear fields exactly at points up to 0.05 μm from the
  // wall, in the feeders, the transitions and the throat; and spreading stays the
  // transpose of interpolation.
  const VesselProfile profile = testing::small_contraction();
  const FluidMesh mesh = make_vessel_fluid_mesh(make_vessel_mesh(profile, VesselMeshSizes{1.0, 0.5}), profile);
  RkpmCoupler coupler(mesh);
  const int count = 400;
  const RkpmCoupler::PointVectors points = testing::points_near_wall(profile, count, 0.05, 0.6, 0.5, 11);
  coupler.update(points);
  std::mt19937 rng(11);
  const double linear = interpolation_error(mesh, coupler, points, [](double x, double y, double z) {
    return std::array<double, 3>{1.0 + 0.3 * x - 0.2 * y + 0.7 * z, -2.0 + y, 0.5 * z - 0.1 * x};
  });
  // ⟨I u, F⟩ = ⟨u, S F⟩ for random u, F.
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Kokkos::View<double*> nodal("u", 4 * mesh.num_dof_nodes), spread("SF", 4 * mesh.num_dof_nodes);
  RkpmCoupler::PointVectors forces("F", count), values("Iu", count);
  auto hn = Kokkos::create_mirror_view(nodal);
  auto hf = Kokkos::create_mirror_view(forces);
  for (std::size_t i = 0; i < hn.extent(0); ++i) hn(i) = u(rng);
  for (int p = 0; p < count; ++p)
    for (int c = 0; c < 3; ++c) hf(p, c) = u(rng);
  Kokkos::deep_copy(nodal, hn);
  Kokkos::deep_copy(forces, hf);
  coupler.interpolate(nodal, 4, values);
  coupler.spread(forces, spread, 4);
  const auto iu = host_copy(values);
  const auto sf = host_copy(spread);
  double left = 0.0, right = 0.0, magnitude = 0.0;
  for (int p = 0; p < count; ++p)
    for (int c = 0; c < 3; ++c) {
      left += iu(p, c) * hf(p, c);
      magnitude += std::fabs(iu(p, c) * hf(p, c));
    }
  for (int n = 0; n < mesh.num_dof_nodes; ++n)
    for (int c = 0; c < 3; ++c) right += hn(4 * n + c) * sf(4 * n + c);
  std::cout << "  vessel (" << mesh.num_elements << " tetrahedra): linear field error " << linear << "; corrected "
            << coupler.corrected_points() << " of " << count << " points; <Iu, F> - <u, SF> = " << left - right << "\n";
  EXPECT_LT(linear, 1e-11);
  EXPECT_EQ(coupler.corrected_points(), count);
  EXPECT_LT(std::fabs(left - right), 1e-13 * magnitude);
}

TEST(Rkpm, RefusesPointsOutsideTheFluid) {
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {10, 10, 10}, {5, 5, 5}, {1, 1, 1}, {false, false, false});
  RkpmCoupler coupler(mesh);
  RkpmCoupler::PointVectors points("points", 1);
  auto h = Kokkos::create_mirror_view(points);
  h(0, 0) = 50.0;
  h(0, 1) = h(0, 2) = 5.0;
  Kokkos::deep_copy(points, h);
  EXPECT_THROW(coupler.update(points), std::runtime_error);
}

// The shape functions against a serial reference that searches every dof node (minimum
// image across the periodic sides), weighs it with the window of its own support (twice
// the largest extent of its elements, from the elements) and corrects with an independent
// 4×4 solve (Eigen): same supports, same values to 1e-12; with the skip (the correction
// only where the plain window does not reproduce linear fields) and without. On a uniform
// box periodic in x and z, and on a walled box graded 16:1 in x (fine at its ends, coarse in
// its middle: the search's bins narrower than the largest support, each searched to its own
// depth).
TEST(Rkpm, ShapeFunctionsMatchASerialSearchOfEveryNode) {
  struct Mesh {
    const char* name;
    FluidMesh mesh;
  };
  const Mesh meshes[] = {
      {"uniform, periodic x and z", make_box_mesh({0, 0, 0}, {20, 10, 10}, {8, 6, 6}, {1, 1, 1}, {true, false, true})},
      {"graded 16:1 along x, walled",
       make_box_mesh({0, 0, 0}, {20, 10, 10}, {16, 6, 6}, {16, 1, 1}, {false, false, false})}};
  for (const Mesh& m_case : meshes) {
    const FluidMesh& mesh = m_case.mesh;
    const auto points = random_points(mesh, 300, 0.0, 21);
    const auto x = host_copy(points);
    const auto coordinates = host_copy(mesh.coordinates);
    const auto element_nodes = host_copy(mesh.element_nodes);
    const double length[3] = {mesh.upper[0] - mesh.lower[0], mesh.upper[1] - mesh.lower[1],
                              mesh.upper[2] - mesh.lower[2]};
    std::map<int, std::array<double, 3>> node_position;  // the first geometric node of each dof node
    for (int n = 0; n < mesh.num_nodes; ++n)
      node_position.emplace(mesh.dof_node_of_node[n],
                            std::array<double, 3>{coordinates(n, 0), coordinates(n, 1), coordinates(n, 2)});
    std::map<int, std::array<double, 3>> node_support;  // a_Jd = 2 × the largest extent of J's elements
    for (int e = 0; e < mesh.num_elements; ++e) {
      std::array<double, 3> extent{};
      for (int d = 0; d < 3; ++d) {
        double low = 1e300, high = -1e300;
        for (int a = 0; a < mesh.nodes_per_element; ++a) {
          low = std::min(low, coordinates(element_nodes(e, a), d));
          high = std::max(high, coordinates(element_nodes(e, a), d));
        }
        extent[d] = high - low;
      }
      for (int a = 0; a < mesh.nodes_per_element; ++a) {
        auto& support = node_support[mesh.dof_node_of_node[element_nodes(e, a)]];
        for (int d = 0; d < 3; ++d) support[d] = std::max(support[d], 2.0 * extent[d]);
      }
    }
    for (const bool always_correct : {false, true}) {
      RkpmCoupler coupler(mesh);
      coupler.always_correct(always_correct);
      coupler.update(points);
      const auto offsets = host_copy(coupler.offsets());
      const auto nodes = host_copy(coupler.nodes());
      const auto phi = host_copy(coupler.shape_functions());
      double largest_difference = 0.0;
      int wrong_supports = 0, corrected = 0;
      for (int p = 0; p < 300; ++p) {
        std::map<int, double> expected;  // node → Φ
        std::map<int, std::array<double, 3>> offset_of;
        Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
        for (const auto& [node, position] : node_position) {
          std::array<double, 3> y{};
          double w = 1.0;
          for (int d = 0; d < 3; ++d) {
            y[d] = position[d] - x(p, d);
            if (mesh.periodic[d]) y[d] -= length[d] * std::round(y[d] / length[d]);
            w *= cubic_bspline_window(y[d] / node_support[node][d]);
          }
          if (!(w > 0.0)) continue;
          expected[node] = w;
          offset_of[node] = y;
          const Eigen::Vector4d hy(1.0, y[0], y[1], y[2]);
          m += w * hy * hy.transpose();
        }
        const auto& first_support = node_support[expected.begin()->first];
        const bool plain = std::fabs(m(0, 0) - 1.0) < 1e-12 &&
                           std::fabs(m(0, 1)) + std::fabs(m(0, 2)) + std::fabs(m(0, 3)) <
                               1e-12 * (first_support[0] + first_support[1] + first_support[2]);
        if (!plain || always_correct) {
          ++corrected;
          const Eigen::Vector4d c = m.partialPivLu().solve(Eigen::Vector4d(1, 0, 0, 0));
          for (auto& [node, value] : expected) {
            const auto& y = offset_of[node];
            value *= c[0] + c[1] * y[0] + c[2] * y[1] + c[3] * y[2];
          }
        }
        std::map<int, double> found;
        for (int k = offsets(p); k < offsets(p + 1); ++k) found[nodes(k)] = phi(k);
        if (found.size() != expected.size()) {
          ++wrong_supports;
          continue;
        }
        for (const auto& [node, value] : expected) {
          if (!found.count(node)) {
            ++wrong_supports;
            break;
          }
          largest_difference = std::max(largest_difference, std::fabs(found[node] - value));
        }
      }
      std::printf("  %s, %s: %d of 300 points corrected, %d wrong supports, largest |Φ − Φ_serial| %.2e\n",
                  m_case.name, always_correct ? "corrected everywhere" : "corrected where needed", corrected,
                  wrong_supports, largest_difference);
      EXPECT_EQ(wrong_supports, 0) << m_case.name;
      EXPECT_LT(largest_difference, 1e-12) << m_case.name;
      EXPECT_GT(corrected, 0) << m_case.name;  // the walls in y need it
      EXPECT_EQ(coupler.corrected_points(), corrected) << m_case.name;
    }
  }
}

// rkpm_interpolate and rkpm_spread on random CSR rows (a stride of 4, as the fluid's
// unknowns) against serial loops: the same values to 1e-14, relative.
TEST(Rkpm, TransferKernelsMatchSerialLoops) {
  const int n_points = 500, n_nodes = 2000, stride = 4;
  std::mt19937 generator(4);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(generator); };
  std::vector<int> row_offsets{0}, row_nodes;
  std::vector<double> row_phi;
  for (int p = 0; p < n_points; ++p) {
    const int length = std::uniform_int_distribution<int>(0, 40)(generator);
    for (int k = 0; k < length; ++k) {
      row_nodes.push_back(std::uniform_int_distribution<int>(0, n_nodes - 1)(generator));
      row_phi.push_back(uniform(-0.2, 1.0));
    }
    row_offsets.push_back(static_cast<int>(row_nodes.size()));
  }
  std::vector<double> nodal(stride * n_nodes), forces(3 * n_points);
  for (double& v : nodal) v = uniform(-1, 1);
  for (double& v : forces) v = uniform(-1, 1);
  auto to_device = [](const auto& values, const char* label) {
    Kokkos::View<typename std::decay_t<decltype(values)>::value_type*> view(std::string(label), values.size());
    auto host = Kokkos::create_mirror_view(view);
    for (std::size_t i = 0; i < values.size(); ++i) host(i) = values[i];
    Kokkos::deep_copy(view, host);
    return view;
  };
  const auto offsets = to_device(row_offsets, "offsets");
  const auto nodes = to_device(row_nodes, "nodes");
  const auto phi = to_device(row_phi, "phi");
  const auto nodal_view = to_device(nodal, "nodal");
  RkpmCoupler::PointVectors values("values", n_points), point_forces("forces", n_points);
  auto host_forces = Kokkos::create_mirror_view(point_forces);
  for (int p = 0; p < n_points; ++p)
    for (int c = 0; c < 3; ++c) host_forces(p, c) = forces[3 * p + c];
  Kokkos::deep_copy(point_forces, host_forces);

  rkpm_interpolate(Kokkos::DefaultExecutionSpace(), offsets, nodes, phi, nodal_view, stride, values);
  using Scatter = Kokkos::Experimental::ScatterView<double*>;
  Kokkos::View<double*> spread("spread", stride * n_nodes);
  Scatter scatter(spread);
  rkpm_spread(Kokkos::DefaultExecutionSpace(), offsets, nodes, phi, point_forces, scatter, stride);
  Kokkos::Experimental::contribute(spread, scatter);

  const auto interpolated = host_copy(values);
  const auto spread_host = host_copy(spread);
  std::vector<double> expected_spread(stride * n_nodes, 0.0);
  double interpolation_error = 0.0, spread_error = 0.0, scale = 0.0;
  for (int p = 0; p < n_points; ++p)
    for (int c = 0; c < 3; ++c) {
      double u = 0.0;
      for (int k = row_offsets[p]; k < row_offsets[p + 1]; ++k) {
        u += row_phi[k] * nodal[stride * row_nodes[k] + c];
        expected_spread[stride * row_nodes[k] + c] += row_phi[k] * forces[3 * p + c];
      }
      interpolation_error = std::max(interpolation_error, std::fabs(interpolated(p, c) - u));
      scale = std::max(scale, std::fabs(u));
    }
  double spread_scale = 0.0;
  for (int i = 0; i < stride * n_nodes; ++i) {
    spread_error = std::max(spread_error, std::fabs(spread_host(i) - expected_spread[i]));
    spread_scale = std::max(spread_scale, std::fabs(expected_spread[i]));
  }
  std::printf("  interpolation: largest difference %.2e of %.2e; spreading: %.2e of %.2e\n", interpolation_error,
              scale, spread_error, spread_scale);
  EXPECT_LE(interpolation_error, 1e-14 * scale);
  EXPECT_LE(spread_error, 1e-14 * spread_scale);
  EXPECT_GT(spread_scale, 0.0);
}

}  // namespace
}  // namespace rouleau
