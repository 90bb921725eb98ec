#pragma once
// An aggregation multigrid preconditioner for the assembled fluid Jacobian (4×4 node
// blocks: u, v, w, p per node), built for the saddle-point systems of the stabilized
// equal-order Navier–Stokes equations, where one-level preconditioners need more GMRES
// iterations the finer the mesh (ILU(0): 20, 40, 65, 92 at 8³…32³; bench/README.md).
//
// Hierarchy (once per mesh): nodes are aggregated by pairwise matching on a geometric
// strength graph (weight 1/|x_a − x_b|² between nodes that share an element;
// solver/pairwise_aggregation.hpp), two passes per level (aggregates of up to 4 nodes),
// until at most `coarsest_nodes` remain. The prolongation P is piecewise constant and keeps the node
// blocks: (P z_c)(4a + i) = z_c(4 I(a) + i); the restriction is Pᵀ.
// Values (every rebuild): Galerkin coarse operators A_{l+1} = Pᵀ A_l P, summed as 4×4
// blocks on the device (each coarse block gathers its fine blocks: no atomics, a fixed
// summation order), the smoother of every level but the coarsest (its inverted diagonal
// blocks, or its ILU(0)), and a sparse LU of the coarsest (Eigen, on the host).
// Apply (one W-cycle: a fixed linear operator, so plain GMRES may use it), on level l
// from x = 0:
//   x = S⁻¹ b;  twice: x += P cycle_{l+1}(Pᵀ (b − A x));  x += S⁻¹ (b − A x)
// with S the level's smoother (the sweeps and the residuals b − A x reading the level's
// matrix rounded to float, by default: solver/multigrid_smoother.hpp). A piecewise-constant P gives coarse operators too stiff for
// the smooth error they must correct, so a V-cycle (one coarse visit) loses accuracy with
// every level; visiting the coarse level twice (or a Krylov K-cycle, Notay 2010) recovers
// it. Measured on the Stokes manufactured problem of bench_fluid_operator (GMRES
// iterations to 1e-8 at n³ = 8³, 16³, 24³, 32³, 48³):
//   aggregates of 8, ILU(0):                        10, 12, 16, 11, 14 (V-cycle: 13, 19 at 16³, 24³)
//   aggregates of 8, 2 block-Jacobi sweeps, ω = 0.7: 14, 21, 27, 24, 25
//   aggregates of 4, 3 block-Jacobi sweeps, ω = 0.6: 11, 14, 16, 12, 14 (2.6× faster than ILU(0) at 48³)
// The default damping is ω = 1.3 / ρ(D⁻¹A) per level (solver/block_jacobi_smoother.hpp): 0.6
// on these boxes, and stable where a fixed 0.6 diverges (elements graded toward walls).
// Block-Jacobi smoothing is weaker than ILU(0) per sweep, and smaller aggregates make up for
// it: the coarse operator is closer to the fine one, at a W-cycle cost still bounded (each
// level has about a quarter of the nodes and is visited twice as often). Chebyshev
// smoothing around the block diagonal diverged (799 iterations at 8³): D⁻¹A of these
// nonsymmetric saddle-point systems has eigenvalues off the real axis.
#include <Kokkos_Core.hpp>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "solver/block_matrix_graph.hpp"
#include "solver/linear_operator.hpp"
#include "solver/multigrid_smoother.hpp"
#include "host_algebra/pairwise_aggregation.hpp"

namespace rouleau {

// The smoother S of every level but the coarsest: solver/multigrid_smoother.hpp.
struct AggregationMultigridSettings {
  int pairwise_passes = 2;                // aggregates of up to 2² nodes per level
  int coarsest_nodes = 200;               // solved by sparse LU
  int max_levels = 12;
  int cycle_index = 2;                    // coarse corrections per visit: 1 V-cycle, 2 W-cycle
  MultigridSmoother smoother = MultigridSmoother::block_jacobi;
  int jacobi_sweeps = 3;                  // block_jacobi: sweeps per smoothing
  double jacobi_damping_times_radius = 1.3;  // block_jacobi: ω ρ(D⁻¹A) on every level
  // block_jacobi: what the sweeps and the residuals read the level matrices in
  MultigridPrecision precision = MultigridPrecision::single_precision;
};

class AggregationMultigrid final : public Preconditioner {
 public:
  // `fine_graph`: the node-block graph of A; `strength`: the node graph's weights.
  AggregationMultigrid(const BlockMatrixGraph& fine_graph, const WeightedGraph& strength,
                       const AggregationMultigridSettings& settings = {});
  ~AggregationMultigrid() override;
  AggregationMultigrid(const AggregationMultigrid&) = delete;
  AggregationMultigrid& operator=(const AggregationMultigrid&) = delete;

  // The numeric setup from the fine matrix's values on `fine_graph` (kept by reference:
  // the fine level smooths and forms residuals with these values).
  void set_values(const Kokkos::View<double*>& fine_values);
  void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const override;

  int num_levels() const { return static_cast<int>(levels_.size()); }
  // Nodes and stored matrix entries of each level, finest first.
  std::vector<int> level_nodes() const;
  std::vector<std::size_t> level_entries() const;
  // "aggregation multigrid, 3 levels of 4913 → 617 → 80 nodes", for logs.
  std::string describe() const;
  // Level l's matrix (graph and values after set_values) and, but on the coarsest level,
  // the coarse node of each of its nodes (a host copy): for tests against a serial
  // reference of the Galerkin products and the cycle.
  const BlockMatrixGraph& level_graph(int l) const;
  Kokkos::View<double*> level_values(int l) const;
  // Level l's matrix rounded to float, as its sweeps and residuals read it (empty when they
  // read level_values(l): double precision, ILU(0) smoothing, the coarsest level).
  Kokkos::View<float*> level_rounded_values(int l) const;
  std::vector<int> level_aggregates(int l) const;
  // The block-Jacobi smoother's damping ω on level l (0 with ILU(0) and on the coarsest).
  double level_jacobi_damping(int l) const;

 private:
  struct Level;
  struct CoarsestSolver;
  // One cycle on level l: solution = M_l⁻¹ rhs (the level's own vectors below the finest).
  void cycle(int level, const Kokkos::View<const double*>& rhs, const Kokkos::View<double*>& solution) const;
  // Level l's residual vector = rhs − A_l x, A_l as its smoother reads it.
  void level_residual(int l, const Kokkos::View<const double*>& rhs, const Kokkos::View<double*>& x) const;

  AggregationMultigridSettings settings_;
  std::vector<std::unique_ptr<Level>> levels_;
  std::unique_ptr<CoarsestSolver> coarsest_;
};

}  // namespace rouleau
