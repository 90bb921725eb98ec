// The starting guess of a Stokes step (fluid/fluid_solver.hpp).
//
// The step's residual is affine, R(U) = A U − b (the cells' linearized stiffness
// included), and GMRES stops at ‖R‖ ≤ gmres_rtol ‖b‖: the smaller the starting residual,
// the fewer iterations. Successive solutions of a time-dependent problem lie close to a
// low-dimensional space, so the guess is the combination of the last k solutions U_i with
// the least residual (the projection of Fischer 1998, "Projection techniques for iterative
// solution of Ax = b with successive right-hand sides", with A's images recomputed every
// step, since the cells change A):
//   min over c of ‖R(Σ c_i U_i)‖ = ‖Σ c_i w_i − b‖,   w_i = A U_i = R(U_i) − R(0).
// The w_i are orthonormalized by Gram–Schmidt (twice), the same combinations applied to the
// U_i (Ũ_j, q_j), and then c̃_j = ⟨q_j, b⟩ = −⟨q_j, R(0)⟩, U₀ = Σ c̃_j Ũ_j; a w_i that the
// others already span (to 1e-10 of its norm) is left out. The linear extrapolation
// 2 U^n − U^{n−1} lies in the span, so U₀'s residual is never larger (before the Dirichlet
// values, which U₀ takes from the boundary conditions).
// The images are A's actions (GMRES's own operator, the cells' stiffness included): per
// step k operator applications, against GMRES iterations of 4–40 of them each.
// Measured over steps 3–12 of the paper scenes (k = 4 against the extrapolation): mean GMRES
// iterations per step aggregation 9.1 → 5.4, stack_shear 19.4 → 14.8, twelve_cells 17.7 →
// 11.6, contraction 11.8 → 7.8, capillary 14.1 → 11.1 (bench/scenes.md).
#include <KokkosBlas1_axpby.hpp>
#include <KokkosBlas1_dot.hpp>
#include <KokkosBlas1_scal.hpp>
#include <utility>

#include "fluid/fluid_solver.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

void FluidSolver::allocate_past_solutions() {
  const int k = settings_.starting_guess_solutions;
  if (k <= 0 || !stokes_ || past_solutions_.extent(1) > 0) return;
  const std::size_t n = state_.extent(0);
  past_solutions_ = decltype(past_solutions_)("rouleau::FluidSolver::past_solutions", n, k);
  guess_states_ = decltype(guess_states_)("rouleau::FluidSolver::guess_states", n, k);
  guess_images_ = decltype(guess_images_)("rouleau::FluidSolver::guess_images", n, k);
}

void FluidSolver::remember_solution() {
  allocate_past_solutions();
  const int k = past_solutions_.extent_int(1);
  if (k == 0) return;
  past_newest_ = (past_newest_ + 1) % k;
  Kokkos::deep_copy(Kokkos::subview(past_solutions_, Kokkos::ALL(), past_newest_), state_);
  past_count_ = std::min(past_count_ + 1, k);
}

void FluidSolver::project_starting_guess(const ImmersedTerms& immersed) {
  if (past_count_ < 2) return;  // with one solution, the extrapolation knows as much
  ProfilingRegion region("rouleau::FluidSolver::project_starting_guess");
  const auto owned = std::make_pair(0, exchange_->num_owned_unknowns());
  // ⟨a, b⟩ over every rank's owned unknowns
  const auto dot = [&](const ConstVector& a, const ConstVector& b) {
    double d = KokkosBlas::dot(Kokkos::subview(a, owned), Kokkos::subview(b, owned));
    exchange_->sum(&d, 1);
    return d;
  };
  const Vector zero_state_residual = residual_;  // the caller's R(0) = −b, left as it is
  const int k = past_solutions_.extent_int(1);
  int kept = 0;
  for (int age = 0; age < past_count_; ++age) {  // newest first
    const Vector u = Kokkos::subview(guess_states_, Kokkos::ALL(), kept);
    const Vector w = Kokkos::subview(guess_images_, Kokkos::ALL(), kept);
    Kokkos::deep_copy(u, Kokkos::subview(past_solutions_, Kokkos::ALL(), (past_newest_ - age + k) % k));
    // w = A u = R(u) − R(0): the operator GMRES applies (the uniform boxes' stencil), with
    // the cells' stiffness
    if (exchange_->spans_ranks()) operator_.start_filling_copies(u);
    operator_.linear_action(u, w);
    add_immersed_stiffness(immersed, u, w, true, StiffnessArgument::direction);
    const double image_norm = exchange_->norm(w);
    for (int pass = 0; pass < 2; ++pass)
      for (int j = 0; j < kept; ++j) {
        const Vector q_j = Kokkos::subview(guess_images_, Kokkos::ALL(), j);
        const double projection = dot(q_j, w);
        KokkosBlas::axpy(-projection, q_j, w);
        KokkosBlas::axpy(-projection, Kokkos::subview(guess_states_, Kokkos::ALL(), j), u);
      }
    const double remainder = exchange_->norm(w);
    if (!(remainder > 1e-10 * image_norm)) continue;
    KokkosBlas::scal(w, 1.0 / remainder, w);
    KokkosBlas::scal(u, 1.0 / remainder, u);
    ++kept;
  }
  if (kept == 0) return;
  // U₀ = Σ_j ⟨q_j, b⟩ Ũ_j
  Kokkos::deep_copy(state_, 0.0);
  for (int j = 0; j < kept; ++j) {
    const double coefficient = -dot(Kokkos::subview(guess_images_, Kokkos::ALL(), j), zero_state_residual);
    KokkosBlas::axpy(coefficient, Kokkos::subview(guess_states_, Kokkos::ALL(), j), state_);
  }
  exchange_->update_copies(state_);
  operator_.impose_dirichlet(state_);
}

}  // namespace rouleau
