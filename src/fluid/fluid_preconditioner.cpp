#include "fluid/fluid_preconditioner.hpp"

#include <spdlog/spdlog.h>

#include <string>

#include "fluid/fast_diagonalization.hpp"
#include "fluid/fluid_matrix.hpp"
#include "solver/aggregation_multigrid.hpp"
#include "solver/block_jacobi.hpp"
#include "solver/ilu0_preconditioner.hpp"

namespace rouleau {

namespace {

// M = I.
class NoPreconditioner final : public FluidPreconditioner {
 public:
  void factor(const FluidOperator&, const ConstVector&) override {}
  void apply(const ConstVector& r, const Vector& z) const override { Kokkos::deep_copy(z, r); }
};

// M = blockdiag(J_AA), the Jacobian's 4×4 node blocks (Dirichlet rows the identity's).
class PointBlockJacobi final : public FluidPreconditioner {
 public:
  explicit PointBlockJacobi(const FluidMesh& mesh)
      : blocks_("rouleau::PointBlockJacobi::blocks", 16 * mesh.num_dof_nodes), jacobi_(mesh.num_dof_nodes) {}
  void factor(const FluidOperator& op, const ConstVector& state) override {
    op.diagonal_blocks(state, blocks_);
    jacobi_.factor(blocks_);
  }
  void apply(const ConstVector& r, const Vector& z) const override { jacobi_.apply(r, z); }

 private:
  Vector blocks_;
  BlockJacobi jacobi_;
};

// The Jacobian assembled on the mesh's graph (4×4 node blocks), for the preconditioners
// that factor or coarsen it.
class AssembledJacobian {
 protected:
  explicit AssembledJacobian(const FluidMesh& mesh)
      : graph_(build_fluid_matrix_graph(mesh)), values_("rouleau::AssembledJacobian::values", graph_.entries.extent(0)) {}
  // values_ = J(state) on graph_ (Dirichlet rows the identity's).
  void assemble(const FluidOperator& op, const ConstVector& state) { op.assemble_jacobian(state, graph_, values_); }
  BlockMatrixGraph graph_;
  Vector values_;
};

// ILU(0) of the assembled Jacobian (KokkosKernels spiluk/sptrsv).
class AssembledIlu0 final : public FluidPreconditioner, private AssembledJacobian {
 public:
  explicit AssembledIlu0(const FluidMesh& mesh) : AssembledJacobian(mesh), ilu0_(graph_.row_map, graph_.entries) {}
  void factor(const FluidOperator& op, const ConstVector& state) override {
    assemble(op, state);
    ilu0_.factor(values_);
  }
  void apply(const ConstVector& r, const Vector& z) const override { ilu0_.apply(r, z); }

 private:
  Ilu0Preconditioner ilu0_;
};

// The aggregation multigrid of the assembled Jacobian, aggregating the nodes by their
// geometric strength (fluid_node_strength).
class AssembledMultigrid final : public FluidPreconditioner, private AssembledJacobian {
 public:
  AssembledMultigrid(const FluidMesh& mesh, const AggregationMultigridSettings& settings)
      : AssembledJacobian(mesh), multigrid_(graph_, fluid_node_strength(mesh), settings) {}
  void factor(const FluidOperator& op, const ConstVector& state) override {
    assemble(op, state);
    multigrid_.set_values(values_);
  }
  void apply(const ConstVector& r, const Vector& z) const override { multigrid_.apply(r, z); }

 private:
  AggregationMultigrid multigrid_;
};

}  // namespace

AggregationMultigridSettings multigrid_settings(const SolverConfig& solver) {
  AggregationMultigridSettings settings;
  settings.smoother = solver.multigrid_smoother;
  settings.precision = solver.multigrid_precision;
  return settings;
}

std::unique_ptr<FluidPreconditioner> make_fluid_preconditioner(const SolverConfig& solver, const FluidMesh& mesh) {
  switch (solver.preconditioner) {
    case PreconditionerType::block_jacobi: return std::make_unique<PointBlockJacobi>(mesh);
    case PreconditionerType::ilu0: return std::make_unique<AssembledIlu0>(mesh);
    // "auto" is resolved from a case (config/derived.cpp, run/simulation.cpp); a solver set
    // up without a case takes the multigrid, which applies everywhere.
    case PreconditionerType::automatic:
    case PreconditionerType::multigrid: return std::make_unique<AssembledMultigrid>(mesh, multigrid_settings(solver));
    case PreconditionerType::fast_diagonalization: {
      // The case loader has checked the box; what remains is where the vectors live.
      const std::string reason = FastDiagonalization::unavailable_reason(mesh);
      if (reason.empty()) return std::make_unique<FastDiagonalization>(mesh);
      spdlog::warn("the fast diagonalization is not available here ({}): the multigrid preconditions the fluid",
                   reason);
      return std::make_unique<AssembledMultigrid>(mesh, multigrid_settings(solver));
    }
    case PreconditionerType::none: break;
  }
  return std::make_unique<NoPreconditioner>();
}

}  // namespace rouleau
