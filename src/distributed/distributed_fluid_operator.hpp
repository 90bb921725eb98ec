#pragma once
// The fluid's Stokes operator and its block-Jacobi preconditioner on the owned unknowns of
// all ranks, for the distributed GMRES (solver/gmres.hpp with a Communicator).
//
// A vector here is a rank's owned entries (4 per owned dof node, the prefix of its local
// vectors). The rank's operator must complete its element sums across ranks
// (FluidOperator::set_node_sums with a NodeSums): then its outputs hold the whole mesh's
// values at every local node, the viscous reconstruction's projected gradient included.
// The action: copy into a local vector, fill the copies (FluidOperator::start_filling_copies:
// they travel while the rank's interior elements are summed), apply the rank's operator
// (FluidOperator::linear_action on the rank's mesh, which carries no Dirichlet rows), keep
// the owned entries, and set the Dirichlet rows to the identity, y_d = x_d —
// as the single-rank operator does.
#include <Kokkos_Core.hpp>
#include <vector>

#include "fluid/fluid_operator.hpp"
#include "fluid/fluid_preconditioner.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"
#include "solver/block_jacobi.hpp"
#include "solver/linear_operator.hpp"

namespace rouleau {

// Throws std::invalid_argument when `local` does not complete its element sums across
// ranks (FluidOperator::set_node_sums); `who` names the caller.
void require_node_sums(const FluidOperator& local, const char* who);

// The local unknown indices of the global unknowns (4·dof node + component) that this
// rank owns, in the order given (the others are left out).
std::vector<int> owned_local_unknowns(const ElementPartition& partition, const std::vector<int>& global_unknowns);

class DistributedStokesOperator final : public LinearOperator {
 public:
  // `local`: the operator on the rank's mesh (make_local_mesh), without Dirichlet rows;
  // `dirichlet`: the owned constrained unknowns (local indices). All must outlive this.
  DistributedStokesOperator(const FluidOperator& local, const ElementPartition& partition,
                            const std::vector<int>& dirichlet);
  void apply(const Kokkos::View<const double*>& x, const Kokkos::View<double*>& y) const override;
  int num_owned_unknowns() const { return owned_; }
  // The owned entries of a local vector and back.
  void owned_part(const Kokkos::View<const double*>& local, const Kokkos::View<double*>& owned) const;

 private:
  const FluidOperator& local_;
  int owned_;
  Kokkos::View<int*> dirichlet_;
  Vector local_x_, local_y_;
};

// Point-block Jacobi across ranks: each owned node's 4×4 diagonal block of the Jacobian
// (completed across ranks by the operator's node sums), Dirichlet rows the identity's,
// inverted node by node.
class DistributedBlockJacobi final : public FluidPreconditioner {
 public:
  DistributedBlockJacobi(const Communicator& communicator, const ElementPartition& partition,
                         const std::vector<int>& dirichlet);
  // `local` must complete its element sums across ranks (set_node_sums).
  // The blocks of `local` at the rank's local `state`.
  void factor(const FluidOperator& local, const ConstVector& state) override;
  // The singular blocks over all ranks at the last factor().
  long long singular_blocks() const { return singular_blocks_; }
  void apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const override;

 private:
  Communicator communicator_;
  int owned_nodes_;
  Kokkos::View<int*> dirichlet_;
  Vector local_blocks_;
  BlockJacobi jacobi_;
  long long singular_blocks_ = 0;
};

}  // namespace rouleau
