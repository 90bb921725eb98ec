// The matrix-free fluid operator against an assembled matrix and against finite
// differences of its residual.
#include <gtest/gtest.h>

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <random>
#include <KokkosBlas1_nrm2.hpp>
#include <KokkosBlas1_update.hpp>
#include <Kokkos_Random.hpp>

#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_matrix.hpp"
#include "fluid/fluid_operator.hpp"
#include "kernels/fluid_assembly.hpp"
#include "kernels/tet4.hpp"
#include "mesh/fluid_mesh.hpp"
#include "test_helpers.hpp"

namespace rouleau {
namespace {

// A tiny graded, partly periodic box of hexahedra or of tetrahedra (the hexahedra cut in
// six), with walls, a moving lid and a traction side.
FluidMesh tiny_mesh(FluidElementType type, std::array<int, 3> elements = {3, 3, 2}) {
  FluidMesh mesh = make_box_mesh({0.0, 0.0, 0.0}, {2.0, 1.0, 1.5}, elements, {1.0, 2.0, 1.0}, {true, false, false});
  return type == FluidElementType::tetrahedron4 ? split_into_tetrahedra(mesh) : mesh;
}

// The tiny box in a Navier–Stokes transient setting with O(1) Reynolds number so every
// term of the element is active. ExecSpace runs the operator's loops (the default space,
// or each host backend).
template <class ExecSpace>
struct TinyProblemOn {
  FluidMesh mesh;
  BasicFluidOperator<ExecSpace> op{mesh, 1.0};
  Vector state{"state", static_cast<size_t>(mesh.num_unknowns())};
  Vector direction{"direction", static_cast<size_t>(mesh.num_unknowns())};
  Vector history{"history", static_cast<size_t>(mesh.num_unknowns())};
  Vector force{"force", static_cast<size_t>(mesh.num_unknowns())};

  TinyProblemOn(FluidElementType type, int convection, int viscous_reconstruction = 0,
                std::array<int, 3> elements = {3, 3, 2})
      : mesh(tiny_mesh(type, elements)) {
    FluidCoefficients c;
    c.viscous_reconstruction = viscous_reconstruction;
    c.reynolds = 3.0;
    c.mass_coefficient = 1.5 / 0.1;
    c.inverse_dt = 1.0 / 0.1;
    c.convection = convection;
    op.set_coefficients(c);
    std::array<BoundaryConfig, 6> sides{};
    sides[Side::x_min].type = sides[Side::x_max].type = BoundaryType::periodic;
    sides[Side::y_max].velocity = {1.0, 0.0, 0.5};
    sides[Side::z_max].type = BoundaryType::traction;
    sides[Side::z_max].pressure = 0.3;
    const auto bc = build_boundary_conditions(mesh, sides, FluidScales{});
    op.set_dirichlet(bc.dirichlet_dofs, bc.dirichlet_values);
    op.set_nodal_load(bc.traction_load);
    Kokkos::Random_XorShift64_Pool<> pool(12345);
    Kokkos::fill_random(state, pool, -1.0, 1.0);
    Kokkos::fill_random(direction, pool, -1.0, 1.0);
    Kokkos::fill_random(history, pool, -1.0, 1.0);
    Kokkos::fill_random(force, pool, -1.0, 1.0);
    op.set_sources(history, force);
  }

  // The global Jacobian assembled from element matrices, with the operator's Dirichlet rows.
  Eigen::SparseMatrix<double> assemble() const {
    const int npe = mesh.nodes_per_element;
    Kokkos::View<double***> matrices("matrices", mesh.num_elements, 4 * npe, 4 * npe);
    op.element_matrices(state, matrices);
    auto k = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), matrices);
    auto conn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_dof_nodes);
    auto dofs = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), op.dirichlet_dofs());
    std::vector<bool> constrained(mesh.num_unknowns(), false);
    for (size_t i = 0; i < dofs.extent(0); ++i) constrained[dofs(i)] = true;
    std::vector<Eigen::Triplet<double>> entries;
    for (int e = 0; e < mesh.num_elements; ++e)
      for (int a = 0; a < npe; ++a)
        for (int i = 0; i < 4; ++i) {
          const int row = 4 * conn(e, a) + i;
          if (constrained[row]) continue;
          for (int b = 0; b < npe; ++b)
            for (int j = 0; j < 4; ++j) entries.emplace_back(row, 4 * conn(e, b) + j, k(e, 4 * a + i, 4 * b + j));
        }
    for (int row = 0; row < mesh.num_unknowns(); ++row)
      if (constrained[row]) entries.emplace_back(row, row, 1.0);
    Eigen::SparseMatrix<double> A(mesh.num_unknowns(), mesh.num_unknowns());
    A.setFromTriplets(entries.begin(), entries.end());
    return A;
  }
};

using TinyProblem = TinyProblemOn<Kokkos::DefaultExecutionSpace>;

// Every test runs on both element types, through the same kernels.
class FluidOperatorOn : public ::testing::TestWithParam<FluidElementType> {};
INSTANTIATE_TEST_SUITE_P(Elements, FluidOperatorOn,
                         ::testing::Values(FluidElementType::hexahedron8, FluidElementType::tetrahedron4),
                         [](const ::testing::TestParamInfo<FluidElementType>& info) {
                           return info.param == FluidElementType::tetrahedron4 ? std::string("Tet4")
                                                                               : std::string("Hex8");
                         });

Eigen::VectorXd to_eigen(const Vector& v) {
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v);
  Eigen::VectorXd e(h.extent(0));
  for (size_t i = 0; i < h.extent(0); ++i) e(i) = h(i);
  return e;
}

TEST_P(FluidOperatorOn, JacobianActionMatchesAssembledMatrix) {
  for (int convection : {0, 1}) {
    TinyProblem p(GetParam(), convection);
    Vector action("action", p.mesh.num_unknowns());
    p.op.jacobian_action(p.state, p.direction, action);
    const Eigen::VectorXd expected = p.assemble() * to_eigen(p.direction);
    const double rel = (to_eigen(action) - expected).norm() / expected.norm();
    std::printf("%s convection=%d: matrix-free vs assembled, relative difference %.2e\n", GetParam() == FluidElementType::tetrahedron4 ? "tet4" : "hex8", convection, rel);
    EXPECT_LT(rel, 1e-12);
  }
}

TEST_P(FluidOperatorOn, JacobianActionMatchesFiniteDifferenceOfResidual) {
  // (R(U + εδ; τ(U)) − R(U − εδ; τ(U))) / 2ε = J(U)δ + O(ε²), τ frozen at U; with and
  // without the projected viscous term in the strong residual (its coupling beyond the
  // element is in the Jacobian action too).
  for (int reconstruction : {0, 1}) {
    TinyProblem p(GetParam(), 1, reconstruction);
    const int n = p.mesh.num_unknowns();
    Vector action("action", n), plus("plus", n), minus("minus", n), shifted("shifted", n), fd("fd", n);
    p.op.jacobian_action(p.state, p.direction, action);
    double errors[2];
    const double eps[2] = {1e-3, 5e-4};
    for (int k = 0; k < 2; ++k) {
      const double e = eps[k];
      // (KokkosBlas rather than lambdas: CUDA forbids extended lambdas in a TEST body.)
      KokkosBlas::update(1.0, p.state, e, p.direction, 0.0, shifted);
      p.op.residual(shifted, p.state, plus);
      KokkosBlas::update(1.0, p.state, -e, p.direction, 0.0, shifted);
      p.op.residual(shifted, p.state, minus);
      KokkosBlas::update(0.5 / e, plus, -0.5 / e, minus, 0.0, fd);
      errors[k] = testing::relativeDifference(fd, action);
    }
    const double order = std::log(errors[0] / errors[1]) / std::log(2.0);
    std::printf("viscous reconstruction %d: finite difference vs Jacobian action: %.2e (eps 1e-3), %.2e (eps 5e-4), "
                "order %.2f\n",
                reconstruction, errors[0], errors[1], order);
    EXPECT_LT(errors[1], 1e-6);
    EXPECT_GT(order, 1.8);  // central differences: second order in ε
  }
}

TEST_P(FluidOperatorOn, ProjectedGradientIsExactForLinearFields) {
  // The lumped projection of ∇u reproduces a constant gradient at every node.
  TinyProblem p(GetParam(), 1);
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.mesh.coordinates);
  // u = A x with A a constant matrix (periodic in x, so no x dependence: A(:,0) = 0).
  const double A[3][3] = {{0, 0.5, -1.0}, {0, 2.0, 0.25}, {0, -0.75, 1.5}};
  auto u = Kokkos::create_mirror_view(p.state);
  for (int node = 0; node < p.mesh.num_nodes; ++node)
    for (int i = 0; i < 3; ++i) {
      u(4 * p.mesh.dof_node_of_node[node] + i) = 0.0;
      for (int j = 0; j < 3; ++j) u(4 * p.mesh.dof_node_of_node[node] + i) += A[i][j] * x(node, j);
    }
  Kokkos::deep_copy(p.state, u);
  Vector gradient("gradient", 9 * p.mesh.num_dof_nodes), expected("expected", 9 * p.mesh.num_dof_nodes);
  p.op.project_gradient(p.state, gradient);
  auto e = Kokkos::create_mirror_view(expected);
  for (int node = 0; node < p.mesh.num_dof_nodes; ++node)
    for (int k = 0; k < 9; ++k) e(9 * node + k) = A[k / 3][k % 3];
  Kokkos::deep_copy(expected, e);
  testing::expectAllClose(gradient, expected, 1e-12, 1e-12);
}

TEST_P(FluidOperatorOn, LinearActionEqualsJacobianActionInStokesLimit) {
  TinyProblem p(GetParam(), 0);
  const int n = p.mesh.num_unknowns();
  Vector jacobian("jacobian", n), linear("linear", n);
  p.op.jacobian_action(p.state, p.direction, jacobian);
  p.op.linear_action(p.direction, linear);
  testing::expectAllClose(linear, jacobian, 1e-13, 1e-13);
}

TEST_P(FluidOperatorOn, SubscaleVelocityActionIsTheLinearPartOfTheSubscaleVelocity) {
  // In the Stokes limit τ_M depends on Δt and h alone, so u'(U) is affine in U and its
  // derivative along δ is u'(U + δ) − u'(U) exactly (the sources cancel), with and without
  // the projected viscous term (whose gradient of δ the action projects itself).
  for (int reconstruction : {0, 1}) {
    TinyProblem p(GetParam(), 0, reconstruction);
    const int n = p.mesh.num_unknowns();
    Vector action("action", n), at_state("at_state", n), shifted("shifted", n), at_shifted("at_shifted", n),
        expected("expected", n);
    p.op.subscale_velocity_action(p.state, p.direction, action);
    p.op.subscale_velocity(p.state, at_state);
    KokkosBlas::update(1.0, p.state, 1.0, p.direction, 0.0, shifted);
    p.op.subscale_velocity(shifted, at_shifted);
    KokkosBlas::update(1.0, at_shifted, -1.0, at_state, 0.0, expected);
    std::printf("viscous reconstruction %d: |u'_delta| %.3e, relative difference from u'(U + delta) - u'(U) %.2e\n",
                reconstruction, KokkosBlas::nrm2(action), testing::relativeDifference(action, expected));
    EXPECT_GT(KokkosBlas::nrm2(action), 1e-3 * KokkosBlas::nrm2(at_state));  // not trivially zero
    testing::expectAllClose(action, expected, 1e-11, 1e-13);
  }
}

TEST_P(FluidOperatorOn, SubscaleVelocityInItsRegionEqualsTheWholeMeshsAtTheRegionsNodes) {
  // On a box of 8 x 6 x 6 elements, u' and its derivative computed on the two rings of
  // elements around a few nodes (subscale_region_around) equal the whole mesh's at those
  // nodes, with and without the projected viscous term, while the rings leave most
  // elements out.
  for (int reconstruction : {0, 1}) {
    TinyProblem p(GetParam(), 1, reconstruction, {8, 6, 6});
    const int n = p.mesh.num_unknowns();
    const std::vector<int> picked{p.mesh.num_dof_nodes / 2, p.mesh.num_dof_nodes / 2 + 1, 3};
    Kokkos::View<int*> nodes("nodes", picked.size());
    auto h = Kokkos::create_mirror_view(nodes);
    for (std::size_t i = 0; i < picked.size(); ++i) h(i) = picked[i];
    Kokkos::deep_copy(nodes, h);
    const SubscaleRegion region = p.op.subscale_region_around(nodes);
    ASSERT_TRUE(region.restricted);
    EXPECT_LT(region.elements.extent(0), static_cast<std::size_t>(p.mesh.num_elements) / 4);
    // The second ring, whatever the coefficients (a run sets them after the region).
    EXPECT_GT(region.gradient_elements.extent(0), region.elements.extent(0));
    EXPECT_LT(region.gradient_elements.extent(0), static_cast<std::size_t>(p.mesh.num_elements));
    Vector whole("whole", n), part("part", n), whole_action("whole_action", n), part_action("part_action", n);
    p.op.subscale_velocity(p.state, whole);
    p.op.subscale_velocity(p.state, part, region);
    p.op.subscale_velocity_action(p.state, p.direction, whole_action);
    p.op.subscale_velocity_action(p.state, p.direction, part_action, region);
    const auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), whole);
    const auto q = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), part);
    const auto wa = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), whole_action);
    const auto qa = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), part_action);
    double largest = 0.0;
    for (int k = 0; k < n; ++k) largest = std::max({largest, std::fabs(w(k)), std::fabs(wa(k))});
    for (int node : picked)
      for (int i = 0; i < 3; ++i) {
        const int k = 4 * node + i;
        EXPECT_NEAR(q(k), w(k), 1e-13 * largest) << "node " << node << " component " << i;
        EXPECT_NEAR(qa(k), wa(k), 1e-13 * largest) << "node " << node << " component " << i;
      }
    // Away from the nodes the region's result is zero or partial, not the whole mesh's.
    int differ = 0;
    for (int k = 0; k < n; ++k) differ += std::fabs(q(k) - w(k)) > 1e-9 * largest ? 1 : 0;
    EXPECT_GT(differ, n / 4) << "reconstruction " << reconstruction;
  }
}

TEST_P(FluidOperatorOn, DiagonalBlocksMatchAssembledMatrix) {
  TinyProblem p(GetParam(), 1);
  Vector blocks("blocks", 16 * p.mesh.num_dof_nodes);
  p.op.diagonal_blocks(p.state, blocks);
  const Eigen::SparseMatrix<double> A = p.assemble();
  Vector expected("expected", blocks.extent(0));
  auto h = Kokkos::create_mirror_view(expected);
  for (int node = 0; node < p.mesh.num_dof_nodes; ++node)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) h(16 * node + 4 * i + j) = A.coeff(4 * node + i, 4 * node + j);
  Kokkos::deep_copy(expected, h);
  testing::expectAllClose(blocks, expected, 1e-12, 1e-12);
}

TEST_P(FluidOperatorOn, CrsAssemblyMatchesElementAssembly) {
  // The CRS Jacobian for assembled preconditioners against the element-matrix assembly.
  TinyProblem p(GetParam(), 1);
  const BlockMatrixGraph graph = build_fluid_matrix_graph(p.mesh);
  Vector values("values", graph.entries.extent(0));
  p.op.assemble_jacobian(p.state, graph, values);
  const Eigen::SparseMatrix<double> A = p.assemble();
  auto row_map = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), graph.row_map);
  auto entries = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), graph.entries);
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), values);
  double difference = 0.0, norm = 0.0, stored = 0.0;
  for (int row = 0; row < graph.num_rows; ++row)
    for (size_t k = row_map(row); k < row_map(row + 1); ++k) {
      difference = std::max(difference, std::fabs(v(k) - A.coeff(row, entries(k))));
      norm = std::max(norm, std::fabs(A.coeff(row, entries(k))));
      stored += A.coeff(row, entries(k)) * A.coeff(row, entries(k));
    }
  // Every nonzero of A lies on the graph: the squared entries on it sum to ‖A‖_F².
  EXPECT_NEAR(stored, A.squaredNorm(), 1e-12 * A.squaredNorm());
  EXPECT_LT(difference, 1e-13 * norm);
}

#if defined(KOKKOS_ENABLE_SERIAL) && defined(KOKKOS_ENABLE_OPENMP) && !defined(KOKKOS_ENABLE_CUDA)
TEST_P(FluidOperatorOn, SerialAndOpenMPBackendsAgreeToRoundOff) {
  // Every pass of the operator on the Serial and the OpenMP backend, same inputs: the
  // only difference allowed is the order of floating-point sums (scatter duplication).
  TinyProblemOn<Kokkos::Serial> serial(GetParam(), 1, 1);
  TinyProblemOn<Kokkos::OpenMP> openmp(GetParam(), 1, 1);
  const int n = serial.mesh.num_unknowns();
  auto compare = [](const char* what, const Vector& a, const Vector& b) {
    const double difference = testing::relativeDifference(a, b);
    std::printf("%-18s Serial vs OpenMP (%d threads): relative difference %.2e\n", what,
                Kokkos::OpenMP().concurrency(), difference);
    EXPECT_LT(difference, 1e-14) << what;
  };
  Vector a("a", n), b("b", n);
  serial.op.residual(serial.state, serial.state, a);
  openmp.op.residual(openmp.state, openmp.state, b);
  compare("residual", a, b);
  serial.op.jacobian_action(serial.state, serial.direction, a);
  openmp.op.jacobian_action(openmp.state, openmp.direction, b);
  compare("jacobian_action", a, b);
  Vector ga("ga", 9 * serial.mesh.num_dof_nodes), gb("gb", 9 * serial.mesh.num_dof_nodes);
  serial.op.project_gradient(serial.state, ga);
  openmp.op.project_gradient(openmp.state, gb);
  compare("project_gradient", ga, gb);
  Vector ba("ba", 16 * serial.mesh.num_dof_nodes), bb("bb", 16 * serial.mesh.num_dof_nodes);
  serial.op.diagonal_blocks(serial.state, ba);
  openmp.op.diagonal_blocks(openmp.state, bb);
  compare("diagonal_blocks", ba, bb);
  const BlockMatrixGraph graph = build_fluid_matrix_graph(serial.mesh);
  Vector ma("ma", graph.entries.extent(0)), mb("mb", graph.entries.extent(0));
  serial.op.assemble_jacobian(serial.state, graph, ma);
  openmp.op.assemble_jacobian(openmp.state, graph, mb);
  compare("assemble_jacobian", ma, mb);
  TinyProblemOn<Kokkos::Serial> serial_stokes(GetParam(), 0, 1);
  TinyProblemOn<Kokkos::OpenMP> openmp_stokes(GetParam(), 0, 1);
  serial_stokes.op.linear_action(serial_stokes.direction, a);
  openmp_stokes.op.linear_action(openmp_stokes.direction, b);
  compare("linear_action", a, b);
}
#endif

// The linear tetrahedron integrated by its 4-point rule: the reference for the closed forms
// the affine element takes in the Stokes limit.
struct Tet4ByQuadrature : Tet4 {
  static constexpr bool affine = false;
};

// Largest |a − b| over the largest |b| of two element arrays.
template <int Rows, int Columns>
double relative_gap(const double (&a)[Rows][Columns], const double (&b)[Rows][Columns]) {
  double gap = 0.0, scale = 0.0;
  for (int r = 0; r < Rows; ++r)
    for (int c = 0; c < Columns; ++c) {
      gap = std::max(gap, std::abs(a[r][c] - b[r][c]));
      scale = std::max(scale, std::abs(b[r][c]));
    }
  return gap / scale;
}

TEST(FluidElement, AffineStokesClosedFormsEqualTheQuadrature) {
  // A skewed tetrahedron, random nodal fields; the residual, the subscale moments, their
  // derivatives along a direction (Dual<1>), the loads' stabilization and the gradient
  // moments in closed form against the same by quadrature (exact for them: degree 2).
  Kokkos::View<double* [3]> coordinates("coordinates", 4);
  Kokkos::View<int**> element_nodes("element_nodes", 1, 4);
  const double corners[4][3] = {{0.1, -0.2, 0.05}, {1.3, 0.1, -0.1}, {0.4, 0.9, 0.2}, {0.2, 0.3, 1.1}};
  for (int a = 0; a < 4; ++a) {
    element_nodes(0, a) = a;
    for (int d = 0; d < 3; ++d) coordinates(a, d) = corners[a][d];
  }
  Kokkos::View<double***> geometry("geometry", 1, Tet4::quadrature_points, geometry_entries);
  Kokkos::View<double*> element_size("element_size", 1);
  int inverted = 0;
  FluidGeometryFunctor<Tet4>{coordinates, element_nodes, 1.0, geometry, element_size}(0, inverted);
  ASSERT_EQ(inverted, 0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  double state[4][4], direction[4][4], frozen[4][3], history[4][3], force[4][3], density[4][3];
  double gradient[36];
  for (int a = 0; a < 4; ++a) {
    for (int c = 0; c < 4; ++c) state[a][c] = uniform(random), direction[a][c] = uniform(random);
    for (int i = 0; i < 3; ++i)
      frozen[a][i] = uniform(random), history[a][i] = uniform(random), force[a][i] = uniform(random),
      density[a][i] = uniform(random);
  }
  for (double& g : gradient) g = uniform(random);
  const double h = element_size(0);
  for (int reconstruction : {0, 1}) {
    FluidCoefficients coef;
    coef.reynolds = 3.0;
    coef.mass_coefficient = 15.0;
    coef.inverse_dt = 10.0;
    coef.convection = 0;
    coef.viscous_reconstruction = reconstruction;
    double closed[4][4] = {}, quadrature[4][4] = {}, closed_moments[4][3] = {}, quadrature_moments[4][3] = {};
    fluid_element_residual<Tet4, double>(coef, geometry, 0, h, state, frozen, history, force, gradient, closed,
                                         closed_moments);
    fluid_element_residual<Tet4ByQuadrature, double>(coef, geometry, 0, h, state, frozen, history, force, gradient,
                                                     quadrature, quadrature_moments);
    fluid_element_load_stabilization<Tet4>(coef, geometry, 0, h, frozen, density, closed, closed_moments);
    fluid_element_load_stabilization<Tet4ByQuadrature>(coef, geometry, 0, h, frozen, density, quadrature,
                                                       quadrature_moments);
    // In dual numbers: the state moved along the direction, the gradient along its own.
    Dual<1> dual_state[4][4], dual_gradient[36], dual_closed[4][4], dual_quadrature[4][4], dual_closed_moments[4][3],
        dual_quadrature_moments[4][3];
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c) {
        dual_state[a][c] = Dual<1>(state[a][c]);
        dual_state[a][c].derivative[0] = direction[a][c];
      }
    for (int k = 0; k < 36; ++k) {
      dual_gradient[k] = Dual<1>(gradient[k]);
      dual_gradient[k].derivative[0] = gradient[(k + 5) % 36];
    }
    fluid_element_residual<Tet4, Dual<1>>(coef, geometry, 0, h, dual_state, frozen, history, force, dual_gradient,
                                          dual_closed, dual_closed_moments);
    fluid_element_residual<Tet4ByQuadrature, Dual<1>>(coef, geometry, 0, h, dual_state, frozen, history, force,
                                                      dual_gradient, dual_quadrature, dual_quadrature_moments);
    double derivative_closed[4][4], derivative_quadrature[4][4], moments_derivative_closed[4][3],
        moments_derivative_quadrature[4][3];
    for (int a = 0; a < 4; ++a) {
      for (int c = 0; c < 4; ++c) {
        derivative_closed[a][c] = dual_closed[a][c].derivative[0];
        derivative_quadrature[a][c] = dual_quadrature[a][c].derivative[0];
      }
      for (int i = 0; i < 3; ++i) {
        moments_derivative_closed[a][i] = dual_closed_moments[a][i].derivative[0];
        moments_derivative_quadrature[a][i] = dual_quadrature_moments[a][i].derivative[0];
      }
    }
    double closed_gradient[4][9], quadrature_gradient[4][9], closed_mass[4], quadrature_mass[4];
    element_gradient_moments<Tet4>(geometry, 0, state, closed_gradient, closed_mass);
    element_gradient_moments<Tet4ByQuadrature>(geometry, 0, state, quadrature_gradient, quadrature_mass);
    double mass_gap = 0.0;
    for (int a = 0; a < 4; ++a) mass_gap = std::max(mass_gap, std::abs(closed_mass[a] / quadrature_mass[a] - 1.0));
    const double gaps[] = {relative_gap(closed, quadrature), relative_gap(closed_moments, quadrature_moments),
                           relative_gap(derivative_closed, derivative_quadrature),
                           relative_gap(moments_derivative_closed, moments_derivative_quadrature),
                           relative_gap(closed_gradient, quadrature_gradient), mass_gap};
    std::printf("viscous reconstruction %d: closed form against quadrature: residual %.1e, subscale moments %.1e, "
                "their derivatives %.1e and %.1e, gradient moments %.1e, lumped mass %.1e\n",
                reconstruction, gaps[0], gaps[1], gaps[2], gaps[3], gaps[4], gaps[5]);
    for (double gap : gaps) EXPECT_LT(gap, 1e-13);
  }
}

TEST_P(FluidOperatorOn, InvertedElementIsRejected) {
  FluidMesh mesh = make_box_mesh({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {1, 1, 1}, {false, false, false});
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  x(13, 0) = 1.8;  // the centre node pushed through the far side
  Kokkos::deep_copy(mesh.coordinates, x);
  if (GetParam() == FluidElementType::tetrahedron4) mesh = split_into_tetrahedra(mesh);
  EXPECT_THROW(FluidOperator(mesh, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace rouleau
