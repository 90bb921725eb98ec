#pragma once
// A preconditioner across ranks stronger than point-block Jacobi: additive
// Schwarz without overlap, each rank's subdomain solved inexactly by ILU(0) or by one cycle
// of the aggregation multigrid of its owned block,
//   M⁻¹ = blockdiag_r S_r⁻¹,   S_r⁻¹ ≈ A_r⁻¹,
// A_r the Jacobian's owned × owned block as the rank's own elements assemble it (rows of
// the shared nodes miss the other ranks' elements off the diagonal), its 4×4 diagonal
// blocks completed by the other ranks' elements (summed at the owner through a NodeHalo of
// 16 components), Dirichlet rows the identity's. On one rank it is the fluid solver's
// ILU(0) or multigrid. No communication in apply(); the iterations grow with the rank count
// as the subdomains shrink (the price of no coarse level across the ranks).
#include <Kokkos_Core.hpp>
#include <memory>
#include <vector>

#include "distributed/node_halo.hpp"
#include "fluid/fluid_matrix.hpp"
#include "fluid/fluid_operator.hpp"
#include "fluid/fluid_preconditioner.hpp"
#include "parallel/element_partition.hpp"
#include "solver/aggregation_multigrid.hpp"
#include "solver/ilu0_preconditioner.hpp"
#include "solver/linear_operator.hpp"

namespace rouleau {

enum class SubdomainSolver { ilu0, multigrid };

class AdditiveSchwarz final : public FluidPreconditioner {
 public:
  // `local_mesh`: the rank's mesh (make_local_mesh); `dirichlet`: the owned constrained
  // unknowns (local indices, owned_local_unknowns). The multigrid aggregates the owned
  // nodes by their geometric strength within the rank (fluid_node_strength).
  AdditiveSchwarz(const Communicator& communicator, const ElementPartition& partition, const FluidMesh& local_mesh,
                  const std::vector<int>& dirichlet, SubdomainSolver solver = SubdomainSolver::ilu0,
                  const AggregationMultigridSettings& multigrid = {});
  ~AdditiveSchwarz() override;
  // The numeric factorization of the Jacobian of `local` (the rank's operator, without
  // Dirichlet rows, completing its element sums across ranks) at the rank's local `state`.
  void factor(const FluidOperator& local, const ConstVector& state) override;
  // z = M⁻¹ r on the rank's owned entries.
  void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const override;

 private:
  int owned_nodes_;
  BlockMatrixGraph local_graph_, owned_graph_;
  Kokkos::View<std::size_t*> owned_entry_source_;  // per owned-graph entry, its local-graph entry
  Kokkos::View<std::size_t*> diagonal_block_;        // per local node, where its own 4×4 block starts
  Kokkos::View<std::size_t*> owned_diagonal_block_;  // the same in the owned graph
  Vector local_values_, owned_values_, local_blocks_;
  NodeHalo block_halo_;
  Kokkos::View<int*> dirichlet_;
  std::unique_ptr<Ilu0Preconditioner> ilu_;             // one of these
  std::unique_ptr<AggregationMultigrid> multigrid_;
};

}  // namespace rouleau
