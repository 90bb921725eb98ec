#include "solver/gmres.hpp"

#include <KokkosBlas1_axpby.hpp>
#include <KokkosBlas1_dot.hpp>
#include <KokkosBlas1_nrm2.hpp>
#include <KokkosBlas1_scal.hpp>
#include <KokkosBlas2_gemv.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
constexpr int initial_basis_columns = 4;
}  // namespace

Gmres::Gmres(int n, const GmresSettings& settings, const Communicator* communicator)
    : settings_(settings),
      communicator_(communicator && communicator->size() > 1 ? communicator : nullptr),
      basis_("rouleau::Gmres::basis", n, std::min(settings.restart + 1, initial_basis_columns)),
      gram_schmidt_(n, settings.restart + 1, communicator_),
      work_("rouleau::Gmres::work", n),
      preconditioned_("rouleau::Gmres::preconditioned", n),
      correction_("rouleau::Gmres::correction", n),
      projection_("rouleau::Gmres::projection", settings.restart + 1) {}

void Gmres::reserve_basis(int columns) {
  const int held = basis_.extent_int(1);
  if (columns <= held) return;
  const int wanted = std::min(settings_.restart + 1, std::max(columns, 2 * held));
  Kokkos::resize(basis_, basis_.extent(0), wanted);
}

double Gmres::norm(const Kokkos::View<const double*>& v) const {
  if (!communicator_) return KokkosBlas::nrm2(v);
  return std::sqrt(communicator_->sum(KokkosBlas::dot(v, v)));
}

GmresResult Gmres::solve(const LinearOperator& A, const Preconditioner& M, const Kokkos::View<const double*>& b,
                         const Kokkos::View<double*>& x, double relative_tolerance) {
  ProfilingRegion region("rouleau::Gmres::solve");
  const int m = settings_.restart;
  GmresResult result;
  const double b_norm = norm(b);
  auto residual_of = [&](const Kokkos::View<double*>& r) {  // r = b − A x
    A.apply(x, r);
    KokkosBlas::axpby(1.0, b, -1.0, r);
    return norm(r);
  };
  double beta = residual_of(work_);
  result.initial_residual = beta;
  const double rtol = relative_tolerance > 0.0 ? relative_tolerance : settings_.relative_tolerance;
  const double target = std::fmax(rtol * b_norm, settings_.absolute_tolerance);
  if (beta <= target || b_norm == 0.0 && beta == 0.0) {
    result.converged = true;
    result.final_residual = beta;
    return result;
  }

  std::vector<double> H((m + 1) * m), cs(m), sn(m), g(m + 1);
  auto h = [&](int i, int j) -> double& { return H[i + (m + 1) * j]; };
  auto projection_host = Kokkos::create_mirror_view(projection_);

  while (result.iterations < settings_.max_iterations) {
    // v_0 = r / β
    auto v0 = Kokkos::subview(basis_, Kokkos::ALL(), 0);
    KokkosBlas::axpby(1.0 / beta, work_, 0.0, v0);
    std::fill(g.begin(), g.end(), 0.0);
    g[0] = beta;
    int k = 0;
    for (; k < m && result.iterations < settings_.max_iterations; ++k) {
      ++result.iterations;
      reserve_basis(k + 2);
      // w = A M⁻¹ v_k
      M.apply(Kokkos::subview(basis_, Kokkos::ALL(), k), preconditioned_);
      auto w = Kokkos::subview(basis_, Kokkos::ALL(), k + 1);
      A.apply(preconditioned_, w);
      // CGS2: h = Vᵀw, w ⟂ V, and ‖w‖.
      auto V = Kokkos::subview(basis_, Kokkos::ALL(), Kokkos::make_pair(0, k + 1));
      const double w_norm = gram_schmidt_.orthogonalize(V, w, &h(0, k));
      h(k + 1, k) = w_norm;
      if (w_norm > 0.0) KokkosBlas::scal(w, 1.0 / w_norm, w);
      // Apply the earlier rotations to the new column, then make one for h(k+1,k).
      for (int j = 0; j < k; ++j) {
        const double t = cs[j] * h(j, k) + sn[j] * h(j + 1, k);
        h(j + 1, k) = -sn[j] * h(j, k) + cs[j] * h(j + 1, k);
        h(j, k) = t;
      }
      const double r = std::hypot(h(k, k), h(k + 1, k));
      cs[k] = r > 0.0 ? h(k, k) / r : 1.0;
      sn[k] = r > 0.0 ? h(k + 1, k) / r : 0.0;
      h(k, k) = r;
      h(k + 1, k) = 0.0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      if (std::fabs(g[k + 1]) <= target || w_norm == 0.0) {
        ++k;
        break;
      }
    }
    // y = H⁻¹ g (upper triangular k×k), x += M⁻¹ V y.
    std::vector<double> y(k, 0.0);
    for (int i = k - 1; i >= 0; --i) {
      double s = g[i];
      for (int j = i + 1; j < k; ++j) s -= h(i, j) * y[j];
      y[i] = s / h(i, i);
    }
    for (int i = 0; i < k; ++i) projection_host(i) = y[i];
    Kokkos::deep_copy(projection_, projection_host);
    auto V = Kokkos::subview(basis_, Kokkos::ALL(), Kokkos::make_pair(0, k));
    KokkosBlas::gemv("N", 1.0, V, Kokkos::subview(projection_, Kokkos::make_pair(0, k)), 0.0, correction_);
    M.apply(correction_, preconditioned_);
    KokkosBlas::axpby(1.0, preconditioned_, 1.0, x);
    beta = residual_of(work_);
    if (beta <= target) {
      result.converged = true;
      break;
    }
  }
  result.final_residual = beta;
  return result;
}

}  // namespace rouleau
