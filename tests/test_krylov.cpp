// The Krylov solver's parts: the fused CGS2 sweeps (GramSchmidt) against a plain serial
// Gram–Schmidt, and restarted GMRES on a nonsymmetric operator with a known solution.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <Kokkos_Random.hpp>
#include <cmath>
#include <vector>

#include "solver/gmres.hpp"
#include "solver/gram_schmidt.hpp"
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
    EXPECT_LE(result.final_residual, 1e-10 * std::sqrt(static_cast<double>(n)) * 10.0);
    // κ(A) ≈ 4/s: the error is bounded by κ times the relative residual.
    EXPECT_LT(rouleau::testing::relativeDifference(x, exact), 1e-10 * 400.0 * 2.0);
  }
}

}  // namespace
