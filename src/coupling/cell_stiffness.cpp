#include "coupling/cell_stiffness.hpp"

#include <stdexcept>
#include <utility>

#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
using NodeVectors = CellStiffness::NodeVectors;

// positions = base + s · displacement
void displace(const NodeVectors& positions, const NodeVectors& base, const NodeVectors& displacement, double s) {
  Kokkos::parallel_for(
      "rouleau::CellStiffness::displace", Kokkos::RangePolicy<ExecSpace>(0, positions.extent(0)),
      KOKKOS_LAMBDA(const int n) {
        for (int d = 0; d < 3; ++d) positions(n, d) = base(n, d) + s * displacement(n, d);
      });
}
}  // namespace

void differenced_forces(const CellPopulation& population, const WallRepulsion* wall,
                        const CellStiffness::ConstNodeVectors& positions, const NodeVectors& scratch,
                        const NodeVectors& out, const Kokkos::View<const int*>& computed_nodes) {
  population.internal_forces_at(positions, out);
  if (wall) {
    wall->compute_forces(positions, population.surface_area_weights(), scratch);
    if (computed_nodes.extent(0) > 0) keep_nodes(scratch, computed_nodes);
    add_node_vectors(out, scratch);
  }
}

CellStiffness::CellStiffness(const int nodes, const RkpmCoupler& rkpm, ForceEvaluation forces,
                             SurfaceInteraction* interaction, const FluidScales& scales)
    : rkpm_(rkpm), forces_(std::move(forces)), interaction_(interaction), scales_(scales) {
  base_positions_ = NodeVectors("rouleau::CellStiffness::base_positions", nodes);
  displaced_positions_ = NodeVectors("rouleau::CellStiffness::displaced_positions", nodes);
  displacement_ = NodeVectors("rouleau::CellStiffness::displacement", nodes);
  base_forces_ = NodeVectors("rouleau::CellStiffness::base_forces", nodes);
  displaced_forces_ = NodeVectors("rouleau::CellStiffness::displaced_forces", nodes);
  change_ = NodeVectors("rouleau::CellStiffness::change", nodes);
  if (interaction_) interaction_change_ = NodeVectors("rouleau::CellStiffness::interaction_change", nodes);
}

void CellStiffness::linearize(const ConstNodeVectors& positions, double dt) {
  dt_ = dt;
  Kokkos::deep_copy(base_positions_, positions);
  forces_(base_positions_, base_forces_);
  ++evaluations_;
  if (interaction_) interaction_->linearize();
}

void CellStiffness::force_change(const Kokkos::View<const double*>& x, const NodeVectors& change) const {
  ProfilingRegion region("rouleau::CellStiffness::force_change");
  if (dt_ <= 0.0) throw std::logic_error("rouleau::CellStiffness: linearize() first");
  // δx_I = Δt U (I û)_I [μm]
  rkpm_.interpolate(x, 4, displacement_);
  const NodeVectors displacement = displacement_;
  const double to_displacement = dt_ * scales_.velocity;
  Kokkos::parallel_for(
      "rouleau::CellStiffness::displacement", Kokkos::RangePolicy<ExecSpace>(0, displacement.extent(0)),
      KOKKOS_LAMBDA(const int n) {
        for (int d = 0; d < 3; ++d) displacement(n, d) *= to_displacement;
      });
  moves_force_change(displacement_, change);
}

void CellStiffness::moves_force_change(const NodeVectors& moves, const NodeVectors& change) const {
  if (dt_ <= 0.0) throw std::logic_error("rouleau::CellStiffness: linearize() first");
  // The largest node move.
  double largest = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::CellStiffness::largest_move", Kokkos::RangePolicy<ExecSpace>(0, moves.extent(0)),
      KOKKOS_LAMBDA(const int n, double& m) {
        for (int d = 0; d < 3; ++d) {
          const double a = moves(n, d) < 0 ? -moves(n, d) : moves(n, d);
          if (a > m) m = a;
        }
      },
      Kokkos::Max<double>(largest));
  if (!(largest > 0.0)) {  // no move (or not finite: the solve reports it)
    Kokkos::deep_copy(change, 0.0);
    return;
  }

  // K δx ≈ [f(x^n + σ δx) − f(x^n)] / σ,   σ = h / max |δx|
  const double sigma = difference_step / largest;
  displace(displaced_positions_, base_positions_, moves, sigma);
  forces_(displaced_positions_, displaced_forces_);
  ++evaluations_;
  const NodeVectors displaced = displaced_forces_, base = base_forces_;
  const double inverse_step = 1.0 / sigma;
  Kokkos::parallel_for(
      "rouleau::CellStiffness::difference", Kokkos::RangePolicy<ExecSpace>(0, change.extent(0)),
      KOKKOS_LAMBDA(const int n) {
        for (int d = 0; d < 3; ++d) change(n, d) = inverse_step * (displaced(n, d) - base(n, d));
      });
  // + K_interaction δx, exact
  if (interaction_) {
    interaction_->force_change(moves, interaction_change_);
    add_node_vectors(change, interaction_change_);
  }
}

void CellStiffness::apply(const Kokkos::View<const double*>& x, const Kokkos::View<double*>& y) const {
  ProfilingRegion region("rouleau::CellStiffness::apply");
  // Ŝ û = −S (K δx) / (P L²)
  force_change(x, change_);
  const NodeVectors change = change_;
  const double to_residual = -1.0 / scales_.force();
  Kokkos::parallel_for(
      "rouleau::CellStiffness::to_residual", Kokkos::RangePolicy<ExecSpace>(0, change.extent(0)),
      KOKKOS_LAMBDA(const int n) {
        for (int d = 0; d < 3; ++d) change(n, d) *= to_residual;
      });
  Kokkos::deep_copy(y, 0.0);
  rkpm_.spread(change_, y, 4);
}

}  // namespace rouleau
