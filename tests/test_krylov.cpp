// The Krylov solver's parts: the fused CGS2 sweeps (GramSchmidt) against a plain serial
// Gram–Schmidt, the level-scheduled triangular solve (ILU(0)'s) against serial
// substitution, and restarted GMRES on a nonsymmetric operator with a known solution.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <KokkosBlas1_nrm2.hpp>
#include <Kokkos_Random.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "solver/gmres.hpp"
#include "solver/gram_schmidt.hpp"
#include "solver/triangular_solver.hpp"
#include "test_helpers.hpp"

namespace {

using Basis = Kokkos::View<double**, Kokkos::LayoutLeft>;

// Serial CGS2 on the host: for each pass, c = Vᵀw from the pass's start, then w −= V c.
void reference_cgs2(const Basis::HostMirror& V, std::vector<double>& w, std::vector<double>& h) {
  const size_t n = V.extent(0), columns = V.extent(1);
  h.assign(columns, 0.0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<double> c(columns, 0.0);
    for (size_t j = 0; j < columns; ++j)
      for (size_t i = 0; i < n; ++i) c[j] += V(i, j) * w[i];
    for (size_t j = 0; j < columns; ++j) {
      for (size_t i = 0; i < n; ++i) w[i] -= c[j] * V(i, j);
      h[j] += c[j];
    }
  }
}

// A random basis with orthonormal columns (serial modified Gram–Schmidt on the host).
Basis random_orthonormal_basis(long n, int columns, unsigned seed) {
  Basis V("test::V", n, columns);
  Kokkos::Random_XorShift64_Pool<> pool(seed);
  Kokkos::fill_random(V, pool, -1.0, 1.0);
  auto hv = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), V);
  for (int j = 0; j < columns; ++j) {
    for (int k = 0; k < j; ++k) {
      double dot = 0.0;
      for (long i = 0; i < n; ++i) dot += hv(i, k) * hv(i, j);
      for (long i = 0; i < n; ++i) hv(i, j) -= dot * hv(i, k);
    }
    double norm = 0.0;
    for (long i = 0; i < n; ++i) norm += hv(i, j) * hv(i, j);
    for (long i = 0; i < n; ++i) hv(i, j) /= std::sqrt(norm);
  }
  Kokkos::deep_copy(V, hv);
  return V;
}

TEST(GramSchmidt, MatchesSerialCgs2AndLeavesWOrthogonal) {
  // Lengths below, at and across the 512-row chunks, and not multiples of four.
  for (const long n : {7L, 512L, 513L, 2049L, 19652L}) {
    for (const int columns : {1, 5, 13}) {
      if (columns > n) continue;
      SCOPED_TRACE("n = " + std::to_string(n) + ", columns = " + std::to_string(columns));
      const Basis V = random_orthonormal_basis(n, columns, 17 + static_cast<unsigned>(n + columns));
      Kokkos::View<double*> w("test::w", n);
      Kokkos::Random_XorShift64_Pool<> pool(99);
      Kokkos::fill_random(w, pool, -1.0, 1.0);
      // A w with a large component along V, so that the second pass has work left.
      auto hv = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), V);
      auto hw = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), w);
      for (long i = 0; i < n; ++i)
        for (int j = 0; j < columns; ++j) hw(i) += 1e3 * (j + 1) * hv(i, j);
      Kokkos::deep_copy(w, hw);
      std::vector<double> w_reference(hw.data(), hw.data() + n), h_reference;
      reference_cgs2(hv, w_reference, h_reference);

      rouleau::GramSchmidt gram_schmidt(n, columns + 2);
      std::vector<double> h(columns);
      const double norm = gram_schmidt.orthogonalize(V, w, h.data());

      auto result = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), w);
      double reference_norm = 0.0, largest_difference = 0.0;
      for (long i = 0; i < n; ++i) {
        reference_norm += w_reference[i] * w_reference[i];
        largest_difference = std::fmax(largest_difference, std::fabs(result(i) - w_reference[i]));
      }
      reference_norm = std::sqrt(reference_norm);
      EXPECT_LE(largest_difference, 1e-12 * 1e3 * columns);
      EXPECT_NEAR(norm, reference_norm, 1e-12 * reference_norm);
      for (int j = 0; j < columns; ++j) {
        EXPECT_NEAR(h[j], h_reference[j], 1e-12 * std::fabs(h_reference[j]) + 1e-12);
        double dot = 0.0;
        for (long i = 0; i < n; ++i) dot += hv(i, j) * result(i);
        EXPECT_LE(std::fabs(dot), 1e-13 * 1e3 * columns) << "column " << j;
      }
    }
  }
}

TEST(GramSchmidt, RejectsABasisLargerThanItsWorkspace) {
  const Basis V = random_orthonormal_basis(100, 4, 5);
  Kokkos::View<double*> w("test::w", 100);
  rouleau::GramSchmidt gram_schmidt(100, 3);
  std::vector<double> h(4);
  EXPECT_THROW(gram_schmidt.orthogonalize(V, w, h.data()), std::logic_error);
}

// A random sparse triangle in CRS (host): up to `per_row` off-diagonal entries per row on
// the triangle's side, in random order, and a dominant diagonal unless `unit` (then none).
struct HostCrs {
  std::vector<std::size_t> row_map{0};
  std::vector<int> entries;
  std::vector<double> values;
};

HostCrs random_triangle(int n, int per_row, rouleau::TriangularPart triangle, bool unit, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  HostCrs t;
  for (int row = 0; row < n; ++row) {
    std::vector<int> columns;
    const int available = triangle == rouleau::TriangularPart::lower ? row : n - 1 - row;
    for (int k = 0; k < std::min(per_row, available); ++k) {
      std::uniform_int_distribution<int> pick(0, available - 1);
      const int offset = pick(rng);
      columns.push_back(triangle == rouleau::TriangularPart::lower ? offset : row + 1 + offset);
    }
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    if (!unit) columns.push_back(row);
    std::shuffle(columns.begin(), columns.end(), rng);
    for (int c : columns) {
      t.entries.push_back(c);
      t.values.push_back(c == row ? 4.0 + value(rng) : value(rng));
    }
    t.row_map.push_back(t.entries.size());
  }
  return t;
}

template <class T>
Kokkos::View<T*> to_device(const std::vector<T>& host, const char* label) {
  Kokkos::View<T*> v(std::string(label), host.size());
  Kokkos::deep_copy(v, Kokkos::View<const T*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(host.data(), host.size()));
  return v;
}

TEST(TriangularSolver, MatchesSerialSubstitutionAndRespectsItsLevels) {
  const int n = 2000;
  for (const rouleau::TriangularPart triangle : {rouleau::TriangularPart::lower, rouleau::TriangularPart::upper}) {
    for (const bool unit : {false, true}) {
      SCOPED_TRACE(std::string(triangle == rouleau::TriangularPart::lower ? "lower" : "upper") + (unit ? ", unit" : ""));
      const HostCrs t = random_triangle(n, 6, triangle, unit, unit ? 3 : 4);
      std::vector<double> b(n), x_reference(n);
      std::mt19937 rng(11);
      std::uniform_real_distribution<double> value(-1.0, 1.0);
      for (double& v : b) v = value(rng);
      // Serial substitution: forward for a lower triangle, backward for an upper one.
      for (int step = 0; step < n; ++step) {
        const int row = triangle == rouleau::TriangularPart::lower ? step : n - 1 - step;
        double sum = b[row], diagonal = 1.0;
        for (std::size_t k = t.row_map[row]; k < t.row_map[row + 1]; ++k)
          if (t.entries[k] == row)
            diagonal = t.values[k];
          else
            sum -= t.values[k] * x_reference[t.entries[k]];
        x_reference[row] = sum / diagonal;
      }
      const rouleau::TriangularSolver solver(to_device(t.row_map, "test::row_map"), to_device(t.entries, "test::entries"),
                                             triangle);
      Kokkos::View<double*> x("test::x", n);
      solver.solve(to_device(t.values, "test::values"), to_device(b, "test::b"), x);
      auto x_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
      double largest = 0.0;
      for (int row = 0; row < n; ++row)
        largest = std::fmax(largest, std::fabs(x_host(row) - x_reference[row]) / (1.0 + std::fabs(x_reference[row])));
      EXPECT_LE(largest, 1e-13);
      // Every row reads only rows of earlier levels, and every row is scheduled once.
      auto order = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), solver.rows_by_level());
      const std::vector<int>& offsets = solver.level_offsets();
      ASSERT_EQ(offsets.back(), n);
      std::vector<int> level_of(n, -1);
      for (int l = 0; l < solver.num_levels(); ++l)
        for (int i = offsets[l]; i < offsets[l + 1]; ++i) level_of[order(i)] = l;
      for (int row = 0; row < n; ++row) {
        ASSERT_GE(level_of[row], 0) << "row " << row << " not scheduled";
        for (std::size_t k = t.row_map[row]; k < t.row_map[row + 1]; ++k)
          if (t.entries[k] != row) EXPECT_LT(level_of[t.entries[k]], level_of[row]) << "row " << row;
      }
      EXPECT_GT(solver.num_levels(), 1);
      EXPECT_LT(solver.num_levels(), n);
    }
  }
}

TEST(TriangularSolver, RejectsAnEntryOnTheWrongSideOfTheDiagonal) {
  // Row 0 of a "lower" triangle reads column 1.
  const std::vector<std::size_t> row_map{0, 2, 3};
  const std::vector<int> entries{0, 1, 1};
  EXPECT_THROW(rouleau::TriangularSolver(to_device(row_map, "test::row_map"), to_device(entries, "test::entries"),
                                         rouleau::TriangularPart::lower),
               std::invalid_argument);
}

// y = A x for the 1D convection–diffusion matrix A = tridiag(−1 − p, 2 + s, −1 + p): p = 0.4
// makes it nonsymmetric, s = 0.01 keeps it well posed but slow for unpreconditioned GMRES.
struct ConvectionDiffusion1D {
  Kokkos::View<const double*> x;
  Kokkos::View<double*> y;
  static constexpr double peclet = 0.4, shift = 0.01;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    const int n = static_cast<int>(x.extent(0));
    double sum = (2.0 + shift) * x(i);
    if (i > 0) sum += (-1.0 - peclet) * x(i - 1);
    if (i + 1 < n) sum += (-1.0 + peclet) * x(i + 1);
    y(i) = sum;
  }
};

class ConvectionDiffusionOperator final : public rouleau::LinearOperator {
 public:
  void apply(const Kokkos::View<const double*>& x, const Kokkos::View<double*>& y) const override {
    Kokkos::parallel_for("test::convection_diffusion", x.extent(0), ConvectionDiffusion1D{x, y});
  }
};

TEST(Gmres, RecoversAKnownSolutionAcrossRestarts) {
  const int n = 3000;
  Kokkos::View<double*> exact("test::exact", n), b("test::b", n);
  Kokkos::Random_XorShift64_Pool<> pool(7);
  Kokkos::fill_random(exact, pool, -1.0, 1.0);
  const ConvectionDiffusionOperator A;
  A.apply(exact, b);
  const rouleau::IdentityPreconditioner identity;
  for (const int restart : {200, 20}) {
    SCOPED_TRACE("restart " + std::to_string(restart));
    rouleau::GmresSettings settings;
    settings.restart = restart;
    settings.relative_tolerance = 1e-10;
    settings.max_iterations = 4000;
    rouleau::Gmres gmres(n, settings);
    Kokkos::View<double*> x("test::x", n);
    const rouleau::GmresResult result = gmres.solve(A, identity, b, x);
    EXPECT_TRUE(result.converged);
    EXPECT_GT(result.iterations, restart / 2);  // the restart path is exercised for 20
    EXPECT_LE(result.final_residual, 1e-10 * KokkosBlas::nrm2(b));  // the tolerance, as asked
    // κ(A) ≈ 4/s: the error is bounded by κ times the relative residual.
    EXPECT_LT(rouleau::testing::relativeDifference(x, exact), 1e-10 * 400.0 * 2.0);
  }
}

}  // namespace
