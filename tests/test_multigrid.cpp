// The aggregation multigrid preconditioner (solver/aggregation_multigrid.hpp) and its host
// pieces: pairwise aggregation, the aggregate graph, the coarsest level's sparse LU. The
// Galerkin products and the W-cycle are checked against a plain dense serial reference
// built in this file from the same aggregates.
#include <gtest/gtest.h>

#include <Kokkos_Random.hpp>
#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <set>
#include <vector>

#include "fluid/boundary_conditions.hpp"
#include "fluid/fluid_matrix.hpp"
#include "fluid/fluid_operator.hpp"
#include "host_algebra/pairwise_aggregation.hpp"
#include "host_algebra/sparse_direct_solver.hpp"
#include "mesh/fluid_mesh.hpp"
#include "solver/aggregation_multigrid.hpp"
#include "solver/block_jacobi_smoother.hpp"

namespace rouleau {
namespace {

TEST(PairwiseAggregation, CoarseGraphSumsTheWeightsBetweenAggregates) {
  // The chain 0 -1- 1 -2- 2 -3- 3, aggregates {0, 1} and {2, 3}: one coarse edge of weight 2;
  // aggregates {0, 2} and {1, 3}: weight 1 + 2 + 3 = 6.
  WeightedGraph chain;
  chain.offsets = {0, 1, 3, 5, 6};
  chain.neighbors = {1, 0, 2, 1, 3, 2};
  chain.weights = {1, 1, 2, 2, 3, 3};
  const WeightedGraph halves = coarsen_graph(chain, {0, 0, 1, 1}, 2);
  EXPECT_EQ(halves.offsets, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(halves.neighbors, (std::vector<int>{1, 0}));
  EXPECT_EQ(halves.weights, (std::vector<double>{2, 2}));
  const WeightedGraph alternate = coarsen_graph(chain, {0, 1, 0, 1}, 2);
  EXPECT_EQ(alternate.weights, (std::vector<double>{6, 6}));
}

TEST(PairwiseAggregation, ThreePassesMakeConnectedAggregatesOfAtMostEightNodes) {
  // A graded 6 × 5 × 4 box of hexahedra (7 × 6 × 5 nodes): every node in one aggregate,
  // at most 2³ nodes each, each connected in the node graph, and at least a fourfold
  // coarsening.
  const FluidMesh mesh = make_box_mesh({0, 0, 0}, {3, 2, 1}, {6, 5, 4}, {1.0, 1.5, 1.0}, {false, false, false});
  const WeightedGraph strength = fluid_node_strength(mesh);
  ASSERT_EQ(strength.num_nodes(), mesh.num_dof_nodes);
  const Aggregation aggregation = aggregate_pairwise(strength, 3);
  const int nodes = mesh.num_dof_nodes;
  std::vector<std::vector<int>> members(aggregation.num_aggregates);
  for (int a = 0; a < nodes; ++a) {
    ASSERT_GE(aggregation.aggregate_of[a], 0);
    ASSERT_LT(aggregation.aggregate_of[a], aggregation.num_aggregates);
    members[aggregation.aggregate_of[a]].push_back(a);
  }
  for (const auto& aggregate : members) {
    ASSERT_GE(aggregate.size(), 1u);
    EXPECT_LE(aggregate.size(), 8u);
    // Connected: a search from the first member within the aggregate reaches all.
    std::set<int> reached{aggregate[0]};
    std::vector<int> frontier{aggregate[0]};
    while (!frontier.empty()) {
      const int a = frontier.back();
      frontier.pop_back();
      for (int k = strength.offsets[a]; k < strength.offsets[a + 1]; ++k) {
        const int b = strength.neighbors[k];
        if (aggregation.aggregate_of[b] == aggregation.aggregate_of[a] && reached.insert(b).second)
          frontier.push_back(b);
      }
    }
    EXPECT_EQ(reached.size(), aggregate.size());
  }
  std::printf("pairwise aggregation, 3 passes: %d nodes -> %d aggregates\n", nodes, aggregation.num_aggregates);
  EXPECT_LE(4 * aggregation.num_aggregates, nodes);
}

TEST(SparseDirectSolver, SolvesANonsymmetricSparseSystem) {
  // A random nonsymmetric sparse matrix with a dominant diagonal, solved twice with new
  // values on the same pattern: residual at round-off.
  const int n = 60;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<std::size_t> row_map{0};
  std::vector<int> columns;
  for (int row = 0; row < n; ++row) {
    std::set<int> pattern{row, (row + 1) % n, (row * 7 + 3) % n, (row * 13 + 5) % n};
    columns.insert(columns.end(), pattern.begin(), pattern.end());
    row_map.push_back(columns.size());
  }
  SparseDirectSolver solver(n, row_map, columns);
  for (int trial = 0; trial < 2; ++trial) {
    std::vector<double> values(columns.size());
    for (int row = 0; row < n; ++row)
      for (std::size_t k = row_map[row]; k < row_map[row + 1]; ++k)
        values[k] = columns[k] == row ? 5.0 + uniform(random) : uniform(random);
    solver.factor(values);
    std::vector<double> b(n), x(n);
    for (double& entry : b) entry = uniform(random);
    solver.solve(b.data(), x.data());
    double worst = 0.0;
    for (int row = 0; row < n; ++row) {
      double r = b[row];
      for (std::size_t k = row_map[row]; k < row_map[row + 1]; ++k) r -= values[k] * x[columns[k]];
      worst = std::max(worst, std::fabs(r));
    }
    EXPECT_LT(worst, 1e-13);
  }
}

TEST(SparseDirectSolver, SingularMatrixThrows) {
  SparseDirectSolver solver(2, {0, 2, 4}, {0, 1, 0, 1});
  EXPECT_THROW(solver.factor({1.0, 2.0, 2.0, 4.0}), std::runtime_error);
}

// ---- the hierarchy against a dense serial reference (plain loops: Eigen's dense
// solvers do not compile under nvcc with host calls from device functions as errors)

// A dense row-major matrix.
struct Dense {
  int rows = 0, columns = 0;
  std::vector<double> entries;
  Dense(int r, int c) : rows(r), columns(c), entries(static_cast<std::size_t>(r) * c, 0.0) {}
  double& operator()(int i, int j) { return entries[static_cast<std::size_t>(i) * columns + j]; }
  double operator()(int i, int j) const { return entries[static_cast<std::size_t>(i) * columns + j]; }
};
using Vec = std::vector<double>;

Dense multiply(const Dense& A, const Dense& B) {
  Dense C(A.rows, B.columns);
  for (int i = 0; i < A.rows; ++i)
    for (int k = 0; k < A.columns; ++k) {
      const double a = A(i, k);
      if (a != 0.0)
        for (int j = 0; j < B.columns; ++j) C(i, j) += a * B(k, j);
    }
  return C;
}

Dense transpose(const Dense& A) {
  Dense T(A.columns, A.rows);
  for (int i = 0; i < A.rows; ++i)
    for (int j = 0; j < A.columns; ++j) T(j, i) = A(i, j);
  return T;
}

Vec multiply(const Dense& A, const Vec& x) {
  Vec y(A.rows, 0.0);
  for (int i = 0; i < A.rows; ++i)
    for (int j = 0; j < A.columns; ++j) y[i] += A(i, j) * x[j];
  return y;
}

Vec subtract(const Vec& a, const Vec& b) {
  Vec c(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) c[i] = a[i] - b[i];
  return c;
}

void add_to(Vec& a, const Vec& b) {
  for (std::size_t i = 0; i < a.size(); ++i) a[i] += b[i];
}

double norm(const Vec& a) {
  double sum = 0.0;
  for (double v : a) sum += v * v;
  return std::sqrt(sum);
}

Dense dense_matrix(const BlockMatrixGraph& graph, const Kokkos::View<double*>& values) {
  auto row_map = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), graph.row_map);
  auto entries = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), graph.entries);
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), values);
  Dense A(graph.num_rows, graph.num_rows);
  for (int row = 0; row < graph.num_rows; ++row)
    for (std::size_t k = row_map(row); k < row_map(row + 1); ++k) A(row, entries(k)) = v(k);
  return A;
}

// The piecewise-constant block prolongation: P(4a + i, 4 I(a) + i) = 1.
Dense prolongation(const std::vector<int>& aggregate_of, int coarse_nodes) {
  Dense P(4 * static_cast<int>(aggregate_of.size()), 4 * coarse_nodes);
  for (std::size_t a = 0; a < aggregate_of.size(); ++a)
    for (int i = 0; i < 4; ++i) P(4 * static_cast<int>(a) + i, 4 * aggregate_of[a] + i) = 1.0;
  return P;
}

// ILU(0) of A on its own sparsity pattern (row-wise IKJ): unit lower L and upper U
// packed in one matrix.
Dense ilu0(const Dense& A) {
  Dense F = A;
  for (int i = 0; i < A.rows; ++i)
    for (int k = 0; k < i; ++k) {
      if (A(i, k) == 0.0) continue;
      F(i, k) /= F(k, k);
      for (int j = k + 1; j < A.columns; ++j)
        if (A(i, j) != 0.0 && A(k, j) != 0.0) F(i, j) -= F(i, k) * F(k, j);
    }
  return F;
}

// L y = r (unit lower), U z = y with the packed factors.
Vec lu_solve(const Dense& F, Vec x) {
  for (int i = 0; i < F.rows; ++i)
    for (int j = 0; j < i; ++j) x[i] -= F(i, j) * x[j];
  for (int i = F.rows - 1; i >= 0; --i) {
    for (int j = i + 1; j < F.columns; ++j) x[i] -= F(i, j) * x[j];
    x[i] /= F(i, i);
  }
  return x;
}

// x = A⁻¹ b by Gaussian elimination with partial pivoting.
Vec dense_solve(Dense A, Vec b) {
  const int n = A.rows;
  for (int k = 0; k < n; ++k) {
    int pivot = k;
    for (int i = k + 1; i < n; ++i)
      if (std::fabs(A(i, k)) > std::fabs(A(pivot, k))) pivot = i;
    for (int j = 0; j < n; ++j) std::swap(A(k, j), A(pivot, j));
    std::swap(b[k], b[pivot]);
    for (int i = k + 1; i < n; ++i) {
      const double factor = A(i, k) / A(k, k);
      for (int j = k; j < n; ++j) A(i, j) -= factor * A(k, j);
      b[i] -= factor * b[k];
    }
  }
  for (int i = n - 1; i >= 0; --i) {
    for (int j = i + 1; j < n; ++j) b[i] -= A(i, j) * b[j];
    b[i] /= A(i, i);
  }
  return b;
}

struct ReferenceLevel {
  Dense A{0, 0}, F{0, 0}, P{0, 0};  // P is empty on the coarsest level
  Dense swept{0, 0};                // A as the residuals and block-Jacobi sweeps read it
  double jacobi_damping = 0.0;      // the block-Jacobi smoother's ω
};

// S⁻¹ b of a level's smoother.
using ReferenceSmoother = std::function<Vec(const ReferenceLevel&, const Vec&)>;

// ILU(0): S = L U.
Vec ilu0_smoothing(const ReferenceLevel& level, const Vec& b) { return lu_solve(level.F, b); }

// `sweeps` sweeps of damped point-block Jacobi from x = 0: x += ω D⁻¹ (b − A x), D the
// 4×4 diagonal blocks of A (each inverted by dense_solve, one column at a time).
Vec block_jacobi_smoothing(const Dense& A, const Vec& b, int sweeps, double damping) {
  const int nodes = A.rows / 4;
  Vec x(b.size(), 0.0);
  for (int s = 0; s < sweeps; ++s) {
    const Vec residual = subtract(b, multiply(A, x));
    for (int node = 0; node < nodes; ++node) {
      Dense block(4, 4);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) block(i, j) = A(4 * node + i, 4 * node + j);
      const Vec update = dense_solve(block, Vec(residual.begin() + 4 * node, residual.begin() + 4 * node + 4));
      for (int i = 0; i < 4; ++i) x[4 * node + i] += damping * update[i];
    }
  }
  return x;
}

// D⁻¹ A x, D the 4×4 diagonal blocks of A.
Vec block_diagonal_solve_of_product(const Dense& A, const Vec& x) {
  const Vec product = multiply(A, x);
  Vec result(x.size());
  for (int node = 0; node < A.rows / 4; ++node) {
    Dense block(4, 4);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) block(i, j) = A(4 * node + i, 4 * node + j);
    const Vec part = dense_solve(block, Vec(product.begin() + 4 * node, product.begin() + 4 * node + 4));
    std::copy(part.begin(), part.end(), result.begin() + 4 * node);
  }
  return result;
}

// ρ(D⁻¹A) by power iteration from the smoother's start vector (entries 1/2 + hash/2¹⁶).
double reference_spectral_radius(const Dense& A, int iterations) {
  Vec x(A.rows);
  for (int i = 0; i < A.rows; ++i) x[i] = 0.5 + static_cast<double>(((i + 1u) * 2654435761u) >> 16) / 65536.0;
  double radius = 0.0;
  for (int k = 0; k < iterations; ++k) {
    const double length = norm(x);
    for (double& entry : x) entry /= length;
    x = block_diagonal_solve_of_product(A, x);
    radius = norm(x);
  }
  return radius;
}

// x = S⁻¹ b; twice: x += P cycle(Pᵀ (b − A x)); x += S⁻¹ (b − A x). Coarsest: exact.
Vec reference_cycle(const std::vector<ReferenceLevel>& levels, std::size_t l, const Vec& b,
                    const ReferenceSmoother& smooth = ilu0_smoothing) {
  const ReferenceLevel& level = levels[l];
  if (l + 1 == levels.size()) return dense_solve(level.A, b);
  Vec x = smooth(level, b);
  const Dense restriction = transpose(level.P);
  for (int visit = 0; visit < 2; ++visit)
    add_to(x, multiply(level.P, reference_cycle(levels, l + 1,
                                                multiply(restriction, subtract(b, multiply(level.swept, x))), smooth)));
  add_to(x, smooth(level, subtract(b, multiply(level.swept, x))));
  return x;
}

// The Jacobian of a small graded box, periodic in x, walls and a moving lid, Navier–Stokes
// with a BDF mass term and a random state, so every block of the 4×4 node blocks is full.
struct SmallJacobian {
  FluidMesh mesh = make_box_mesh({0, 0, 0}, {2.0, 1.0, 1.0}, {5, 4, 3}, {1.0, 1.5, 1.0}, {true, false, false});
  BlockMatrixGraph graph = build_fluid_matrix_graph(mesh);
  Kokkos::View<double*> values{"values", graph.entries.extent(0)};

  SmallJacobian() {
    FluidOperator op(mesh, 1.0);
    FluidCoefficients c;
    c.reynolds = 2.0;
    c.convection = 1;
    c.mass_coefficient = 1.5 / 0.1;
    c.inverse_dt = 1.0 / 0.1;
    op.set_coefficients(c);
    std::array<BoundaryConfig, 6> sides{};
    sides[Side::x_min].type = sides[Side::x_max].type = BoundaryType::periodic;
    sides[Side::y_max].velocity = {1.0, 0.0, 0.0};
    const auto bc = build_boundary_conditions(mesh, sides, FluidScales{});
    op.set_dirichlet(bc.dirichlet_dofs, bc.dirichlet_values);
    Kokkos::View<double*> state("state", mesh.num_unknowns());
    Kokkos::Random_XorShift64_Pool<> pool(2024);
    Kokkos::fill_random(state, pool, -1.0, 1.0);
    op.impose_dirichlet(state);
    op.assemble_jacobian(state, graph, values);
  }
};

// The hierarchy's Galerkin products and one W-cycle with `settings`' smoother against the
// dense reference with `smooth`.
void expect_cycle_matches_the_dense_reference(AggregationMultigridSettings settings, const ReferenceSmoother& smooth) {
  SmallJacobian problem;
  settings.coarsest_nodes = 4;  // several levels on a small mesh
  AggregationMultigrid multigrid(problem.graph, fluid_node_strength(problem.mesh), settings);
  multigrid.set_values(problem.values);
  std::printf("%s\n", multigrid.describe().c_str());
  ASSERT_GE(multigrid.num_levels(), 3);

  std::vector<ReferenceLevel> reference(multigrid.num_levels());
  reference[0].A = dense_matrix(problem.graph, problem.values);
  for (int l = 0; l < multigrid.num_levels(); ++l) {
    ReferenceLevel& level = reference[l];
    level.F = ilu0(level.A);
    if (l + 1 == multigrid.num_levels()) break;
    const int coarse_nodes = multigrid.level_graph(l + 1).num_rows / 4;
    level.P = prolongation(multigrid.level_aggregates(l), coarse_nodes);
    // A_{l+1} = Pᵀ A_l P, and every nonzero of it lies on the coarse graph.
    const Dense galerkin = multiply(transpose(level.P), multiply(level.A, level.P));
    const Dense stored = dense_matrix(multigrid.level_graph(l + 1), multigrid.level_values(l + 1));
    double difference = 0.0, largest = 0.0;
    for (std::size_t k = 0; k < galerkin.entries.size(); ++k) {
      difference = std::max(difference, std::fabs(stored.entries[k] - galerkin.entries[k]));
      largest = std::max(largest, std::fabs(galerkin.entries[k]));
    }
    EXPECT_LT(difference, 1e-12 * largest) << "level " << l + 1;
    reference[l + 1].A = galerkin;
  }
  // What the residuals and sweeps read: in single precision each entry of the stored level
  // matrix (the Galerkin products just compared) rounded to float, exactly.
  const bool rounded = settings.smoother == MultigridSmoother::block_jacobi &&
                       settings.precision == MultigridPrecision::single_precision;
  for (int l = 0; l < multigrid.num_levels(); ++l) {
    ReferenceLevel& level = reference[l];
    level.swept = level.A;
    const Kokkos::View<float*> stored_rounded = multigrid.level_rounded_values(l);
    if (!rounded || l + 1 == multigrid.num_levels()) {
      EXPECT_EQ(stored_rounded.extent(0), 0u) << "level " << l;
      continue;
    }
    const Kokkos::View<double*> values = multigrid.level_values(l);
    ASSERT_EQ(stored_rounded.extent(0), values.extent(0)) << "level " << l;
    auto values_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), values);
    auto rounded_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), stored_rounded);
    Kokkos::View<double*> widened("widened", values.extent(0));
    auto widened_host = Kokkos::create_mirror_view(widened);
    int mismatches = 0;
    for (std::size_t e = 0; e < values.extent(0); ++e) {
      mismatches += rounded_host(e) != static_cast<float>(values_host(e));
      widened_host(e) = static_cast<double>(static_cast<float>(values_host(e)));
    }
    EXPECT_EQ(mismatches, 0) << "level " << l;
    Kokkos::deep_copy(widened, widened_host);
    level.swept = dense_matrix(multigrid.level_graph(l), widened);
  }
  // The block-Jacobi damping ω = c / ρ(D⁻¹A), ρ from the same power iteration in serial.
  for (int l = 0; l + 1 < multigrid.num_levels(); ++l) {
    reference[l].jacobi_damping = multigrid.level_jacobi_damping(l);
    if (settings.smoother != MultigridSmoother::block_jacobi) continue;
    const double radius = reference_spectral_radius(reference[l].swept, BlockJacobiSmoother::power_iterations);
    std::printf("level %d: rho(D^-1 A) estimated %.4f, damping %.4f\n", l, radius, reference[l].jacobi_damping);
    EXPECT_NEAR(reference[l].jacobi_damping, settings.jacobi_damping_times_radius / radius, 1e-10) << "level " << l;
  }

  const int n = problem.graph.num_rows;
  Kokkos::View<double*> r("r", n), z("z", n);
  Kokkos::Random_XorShift64_Pool<> pool(99);
  Kokkos::fill_random(r, pool, -1.0, 1.0);
  multigrid.apply(r, z);
  auto r_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r);
  auto z_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), z);
  const Vec expected = reference_cycle(reference, 0, Vec(r_host.data(), r_host.data() + n), smooth);
  const double error = norm(subtract(Vec(z_host.data(), z_host.data() + n), expected)) / norm(expected);
  std::printf("W-cycle against the dense reference: relative difference %.2e\n", error);
  EXPECT_LT(error, 1e-10);
}

TEST(AggregationMultigrid, GalerkinProductsAndIlu0SmoothedWCycleMatchADenseReference) {
  // ILU(0) smoothing on aggregates of up to 8 nodes (three pairwise passes).
  AggregationMultigridSettings settings;
  settings.smoother = MultigridSmoother::ilu0;
  settings.pairwise_passes = 3;
  expect_cycle_matches_the_dense_reference(settings, ilu0_smoothing);
}

TEST(AggregationMultigrid, BlockJacobiSmoothedWCycleMatchesADenseReference) {
  // The default hierarchy (aggregates of up to 4 nodes) with one, two and three sweeps:
  // the sweeps alternate between two buffers, so odd and even counts take different paths
  // to the result. Each level's damping is checked against a serial power iteration. In
  // single precision the reference reads the level matrices rounded to float where the
  // cycle should (sweeps and residuals) and in double elsewhere; a reference reading the
  // double values throughout differs from the single-precision cycle by 5e-8 to 8e-8.
  for (const MultigridPrecision precision :
       {MultigridPrecision::double_precision, MultigridPrecision::single_precision}) {
    for (int sweeps : {1, 2, 3}) {
      AggregationMultigridSettings settings;
      settings.smoother = MultigridSmoother::block_jacobi;
      settings.jacobi_sweeps = sweeps;
      settings.precision = precision;
      SCOPED_TRACE(std::string(precision == MultigridPrecision::single_precision ? "single" : "double") +
                   " precision, sweeps " + std::to_string(sweeps));
      expect_cycle_matches_the_dense_reference(settings, [sweeps](const ReferenceLevel& level, const Vec& b) {
        return block_jacobi_smoothing(level.swept, b, sweeps, level.jacobi_damping);
      });
    }
  }
}

TEST(AggregationMultigrid, OneLevelIsAnExactSolve) {
  // With the coarsest level the fine one, M⁻¹ = A⁻¹ (the sparse LU): M⁻¹ A x = x.
  SmallJacobian problem;
  AggregationMultigridSettings settings;
  settings.coarsest_nodes = problem.mesh.num_dof_nodes;
  AggregationMultigrid multigrid(problem.graph, fluid_node_strength(problem.mesh), settings);
  multigrid.set_values(problem.values);
  ASSERT_EQ(multigrid.num_levels(), 1);
  const Dense A = dense_matrix(problem.graph, problem.values);
  const int n = problem.graph.num_rows;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vec x(n);
  for (double& entry : x) entry = uniform(random);
  const Vec Ax = multiply(A, x);
  Kokkos::View<double*> r("r", n), z("z", n);
  auto r_host = Kokkos::create_mirror_view(r);
  for (int i = 0; i < n; ++i) r_host(i) = Ax[i];
  Kokkos::deep_copy(r, r_host);
  multigrid.apply(r, z);
  auto z_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), z);
  double worst = 0.0;
  for (int i = 0; i < n; ++i) worst = std::max(worst, std::fabs(z_host(i) - x[i]));
  EXPECT_LT(worst, 1e-10);
}

}  // namespace
}  // namespace rouleau
