#pragma once
// What the fluid solver needs from the ranks its mesh is split across, and all it knows of
// them: on one rank every operation is the identity (SingleRankExchange, below); across
// ranks distributed/fluid_distribution.hpp implements it with MPI.
//
// A local vector holds the rank's dof nodes (owned first, then copies of other ranks'
// nodes), 4 unknowns per node, node-interleaved; a global vector holds every dof node of
// the whole mesh in the global numbering, the same on every rank.
#include <Kokkos_Core.hpp>
#include <memory>
#include <vector>

#include "config/case_config.hpp"
#include "fluid/element_sum_exchange.hpp"
#include "fluid/fluid_preconditioner.hpp"
#include "mesh/fluid_mesh.hpp"
#include "parallel/communicator.hpp"

namespace rouleau {

class FluidExchange {
 public:
  virtual ~FluidExchange() = default;

  // Whether the mesh is split across more than one rank.
  virtual bool spans_ranks() const = 0;
  // The rank's part of the mesh (the whole mesh on one rank).
  virtual const FluidMesh& local_mesh() const = 0;
  // What completes the element sums across ranks (FluidOperator::set_node_sums), or null.
  virtual const ElementSumExchange* element_sums() const = 0;
  // The ranks, for the Krylov solver's reductions, or null on one rank.
  virtual const Communicator* ranks() const = 0;

  // The dof nodes this rank owns (the first ones of its local vectors).
  virtual int num_owned_nodes() const = 0;
  int num_owned_unknowns() const { return fluid_unknowns_per_node * num_owned_nodes(); }
  // The local dof node of a global one, or −1 when the rank holds none.
  virtual int local_node(int global_node) const = 0;

  // values[i] ← Σ_ranks values[i], i < count, in place.
  virtual void sum(double* values, int count) const = 0;
  // ‖x‖ of a local vector over the unknowns of all ranks (each once).
  virtual double norm(const ConstVector& x) const = 0;
  // The copies of a local vector take their owners' values.
  virtual void update_copies(const Vector& local) const = 0;
  // local ← global at every local dof node.
  virtual void localize(const ConstVector& global, const Vector& local) const = 0;
  // global ← every rank's owned entries of `local`; at the global dof nodes `nodes` alone
  // when given (the other entries of `global` are left as they are).
  virtual void replicate(const ConstVector& local, const Vector& global,
                         const Kokkos::View<const int*>& nodes = {}) const = 0;
  // global ← Σ_ranks global at the global dof nodes `nodes`, where each rank holds its
  // share of a sum (the forces its cells spread).
  virtual void sum_at_nodes(const Vector& global, const Kokkos::View<const int*>& nodes) const = 0;
  // The union of every rank's `nodes` (global dof nodes), ascending, the same on every rank.
  virtual Kokkos::View<const int*> nodes_of_any_rank(const Kokkos::View<const int*>& nodes) const = 0;

  // The preconditioner that `solver` names for the rank's part of the mesh;
  // `owned_dirichlet`: the constrained unknowns among the owned ones (local indices).
  virtual std::unique_ptr<FluidPreconditioner> make_preconditioner(const SolverConfig& solver,
                                                                   const std::vector<int>& owned_dirichlet) const = 0;
};

// One rank: the whole mesh, and every exchange the identity.
class SingleRankExchange final : public FluidExchange {
 public:
  // `mesh` must outlive the exchange.
  explicit SingleRankExchange(const FluidMesh& mesh) : mesh_(mesh) {}
  bool spans_ranks() const override { return false; }
  const FluidMesh& local_mesh() const override { return mesh_; }
  const ElementSumExchange* element_sums() const override { return nullptr; }
  const Communicator* ranks() const override { return nullptr; }
  int num_owned_nodes() const override { return mesh_.num_dof_nodes; }
  int local_node(int global_node) const override { return global_node; }
  void sum(double*, int) const override {}
  double norm(const ConstVector& x) const override;
  void update_copies(const Vector&) const override {}
  void localize(const ConstVector& global, const Vector& local) const override { Kokkos::deep_copy(local, global); }
  void replicate(const ConstVector& local, const Vector& global, const Kokkos::View<const int*>& = {}) const override {
    Kokkos::deep_copy(global, local);
  }
  void sum_at_nodes(const Vector&, const Kokkos::View<const int*>&) const override {}
  Kokkos::View<const int*> nodes_of_any_rank(const Kokkos::View<const int*>& nodes) const override { return nodes; }
  std::unique_ptr<FluidPreconditioner> make_preconditioner(const SolverConfig& solver,
                                                           const std::vector<int>&) const override {
    return make_fluid_preconditioner(solver, mesh_);
  }

 private:
  const FluidMesh& mesh_;
};

}  // namespace rouleau
