#pragma once
// The smoother of the aggregation multigrid's levels (solver/aggregation_multigrid.hpp),
// as the case file names it (solver.multigrid_smoother). Host-only: no Kokkos header, so
// the case's settings can hold it.
namespace rouleau {

// block_jacobi: damped point-block Jacobi sweeps, one fully parallel pass each
//   (solver/block_jacobi_smoother.hpp);
// ilu0: ILU(0) with level-scheduled triangular solves, one kernel launch per level of
//   the schedule (solver/ilu0_preconditioner.hpp).
enum class MultigridSmoother { block_jacobi, ilu0 };

}  // namespace rouleau
