#pragma once
// The preconditioners of the fluid's Jacobian, behind one interface: each is rebuilt from
// the operator at a state (FluidSolver: every Newton step, or once while the Stokes
// operator is constant) and then applied inside GMRES. On one rank (here): point-block
// Jacobi, ILU(0) or the aggregation multigrid of the assembled Jacobian, or none; across
// ranks the exchange makes its own (FluidExchange::make_preconditioner).
#include <Kokkos_Core.hpp>
#include <memory>

#include "config/case_config.hpp"
#include "fluid/fluid_operator.hpp"
#include "solver/aggregation_multigrid.hpp"
#include "solver/linear_operator.hpp"

namespace rouleau {

class FluidPreconditioner : public Preconditioner {
 public:
  // Rebuilds M from the Jacobian of `op` at `state` (the rank's local vectors).
  virtual void factor(const FluidOperator& op, const ConstVector& state) = 0;
};

// The aggregation multigrid's settings that `solver` chooses (its smoother).
AggregationMultigridSettings multigrid_settings(const SolverConfig& solver);

// One rank's preconditioner that `solver` names (solver.preconditioner, and the multigrid's
// smoother) for the fluid on `mesh`.
std::unique_ptr<FluidPreconditioner> make_fluid_preconditioner(const SolverConfig& solver, const FluidMesh& mesh);

}  // namespace rouleau
