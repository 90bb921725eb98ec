#pragma once
// A multigrid smoother of fully parallel passes: `sweeps` sweeps of damped point-block
// Jacobi on an assembled 4×4-block matrix A (solver/block_matrix_graph.hpp), from z = 0:
//   z_0 = 0,   z_{s+1} = z_s + ω D⁻¹ (r − A z_s),   M⁻¹ r = z_sweeps
// with D the 4×4 diagonal blocks (each node's u, v, w, p). Each sweep is one pass over the
// matrix's rows, node by node (the four rows' residual, then the block product), into a
// second buffer: no triangular solve and no level schedule, so one kernel per sweep
// whatever the mesh.
//
// The damping follows the matrix: ω = c / ρ(D⁻¹A), with ρ estimated at every factor() by
// power iteration (a fixed start and count, so equal values give equal ω). A fixed ω is
// stable only while ω ρ < 2 for D⁻¹A's real eigenvalues: ω = 0.6 smooths the uniform shear
// boxes (ρ ≈ 2.1) but diverges on a channel graded toward its walls (48×24×3 elements,
// ρ ≈ 3.9), where GMRES then stalls; c = 1.3 gives ω ≈ 0.6 on the boxes and 0.34 there.
//
// Given a float copy of the values (factor(values, rounded_values)), the sweeps read A
// there: the same arithmetic in double on half the bytes. D, its inverse and ρ are then
// those of the rounded matrix, so the sweeps are exactly damped Jacobi on it.
#include <Kokkos_Core.hpp>

#include "solver/block_jacobi.hpp"
#include "solver/block_matrix_graph.hpp"
#include "solver/linear_operator.hpp"

namespace rouleau {

class BlockJacobiSmoother final : public MatrixPreconditioner {
 public:
  // `damping_times_radius`: c in ω = c / ρ(D⁻¹A).
  BlockJacobiSmoother(const BlockMatrixGraph& graph, int sweeps, double damping_times_radius);
  // Inverts A's diagonal blocks, estimates ρ(D⁻¹A) and keeps `values` (by reference) for
  // the sweeps.
  void factor(const Kokkos::View<double*>& values) override;
  // The same on `rounded_values` (A rounded to float, kept by reference), when not empty.
  void factor(const Kokkos::View<double*>& values, const Kokkos::View<const float*>& rounded_values) override;
  void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const override;

  // After factor(): the estimate of ρ(D⁻¹A) and the damping ω it gave.
  double spectral_radius() const { return spectral_radius_; }
  double damping() const { return damping_; }

  // Power-iteration steps per factor().
  static constexpr int power_iterations = 15;

 private:
  BlockMatrixGraph graph_;
  int sweeps_;
  double damping_times_radius_;
  double spectral_radius_ = 0.0, damping_ = 0.0;
  Kokkos::View<const double*> values_;         // A, when the sweeps read double
  Kokkos::View<const float*> rounded_values_;  // A rounded to float, when they read that
  Kokkos::View<double*> diagonal_blocks_, other_, power_vector_;
  BlockJacobi inverse_;
};

}  // namespace rouleau
