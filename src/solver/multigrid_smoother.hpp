#pragma once
// The smoother of the aggregation multigrid's levels (solver/aggregation_multigrid.hpp) and
// the precision its sweeps read the matrices in, as the case file names them
// (solver.multigrid_smoother, solver.multigrid_precision). Host-only: no Kokkos header, so
// the case's settings can hold it.
namespace rouleau {

// block_jacobi: damped point-block Jacobi sweeps, one fully parallel pass each
//   (solver/block_jacobi_smoother.hpp);
// ilu0: ILU(0) with level-scheduled triangular solves, one kernel launch per level of
//   the schedule (solver/ilu0_preconditioner.hpp).
enum class MultigridSmoother { block_jacobi, ilu0 };

// What the block-Jacobi sweeps and the cycle's residuals read the level matrices in
// (solver.multigrid_precision). They are memory-bound passes over 16 values per node pair,
// so float copies halve their traffic. The arithmetic stays in double, as do the Galerkin
// products and the coarsest level's LU: the preconditioner is still one fixed linear
// operator, and GMRES (in double) converges to the same tolerance. ILU(0) smoothing reads
// the double values whatever this says.
enum class MultigridPrecision { single_precision, double_precision };

}  // namespace rouleau
