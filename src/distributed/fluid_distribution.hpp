#pragma once
// The fluid mesh of a run split across its ranks (docs/mpi.md), as the fluid solver sees it:
// the rank's part of the mesh (make_local_mesh), the node sums that complete its element
// sums (FluidOperator::set_node_sums), the halo that fills its copies, and the maps between
// its local vectors and the global ones (4 unknowns per dof node, node-interleaved).
//
// A local vector holds the rank's owned dof nodes first, then its copies; every local entry
// holds the value the whole mesh gives (copies equal their owners). A global vector holds
// every dof node of the mesh in the global numbering and is the same on every rank.
// replicate() builds one from the owned entries of every rank: an MPI_Allreduce of
// vectors that are zero except at each rank's owned entries, so each global entry is one
// rank's value plus zeros — the same bit for bit for any rank count. It moves the whole
// vector: it is for what needs the whole fluid on every rank (cells replicated on every
// rank, output, checkpoints), not for the solver's inner loop.
#include <Kokkos_Core.hpp>
#include <array>
#include <vector>

#include "distributed/node_halo.hpp"
#include "fluid/fluid_exchange.hpp"
#include "kernels/point_bins.hpp"
#include "distributed/node_sums.hpp"
#include "mesh/fluid_mesh.hpp"
#include "parallel/communicator.hpp"
#include "parallel/element_partition.hpp"

namespace rouleau {

class FluidDistribution final : public FluidExchange {
 public:
  using Vector = Kokkos::View<double*>;
  using ConstVector = Kokkos::View<const double*>;

  // Partitions `global_mesh` (partition_fluid_mesh) for this rank of `communicator`.
  FluidDistribution(const Communicator& communicator, const FluidMesh& global_mesh);
  // Its node sums refer to it: it stays where it was made.
  FluidDistribution(const FluidDistribution&) = delete;
  FluidDistribution& operator=(const FluidDistribution&) = delete;

  // The mesh is split by a partition (of one rank, too: its local vectors then have no copies).
  bool spans_ranks() const override { return true; }
  const Communicator& communicator() const { return communicator_; }
  const Communicator* ranks() const override { return &communicator_; }
  const ElementPartition& partition() const { return partition_; }
  const FluidMesh& local_mesh() const override { return local_mesh_; }
  // The node sums for the rank's FluidOperator (FluidOperator::set_node_sums).
  const NodeSums& node_sums() const { return node_sums_; }
  const ElementSumExchange* element_sums() const override { return &node_sums_; }
  int num_owned_nodes() const override { return partition_.num_owned_nodes; }

  int num_owned_unknowns() const { return fluid_unknowns_per_node * partition_.num_owned_nodes; }
  int num_local_unknowns() const { return fluid_unknowns_per_node * partition_.num_local_nodes(); }
  int num_global_unknowns() const { return fluid_unknowns_per_node * partition_.num_global_nodes; }

  // The copies of a local vector take their owners' values.
  void update_copies(const Vector& local) const override { halo_.update_copies(local); }
  // values[i] ← Σ_ranks values[i] (one MPI_Allreduce).
  void sum(double* values, int count) const override { communicator_.sum(values, count); }
  // Σ x·y and ‖x‖ over the owned entries of all ranks (each unknown once).
  double dot(const ConstVector& x, const ConstVector& y) const;
  double norm(const ConstVector& x) const override;

  // global ← every rank's owned entries of `local` (see above); the same on every rank.
  // With `nodes`, at those global dof nodes alone (the cells' supports): one
  // MPI_Allreduce of 4 values per node; the other entries of `global` are left as they are.
  void replicate(const ConstVector& local, const Vector& global,
                 const Kokkos::View<const int*>& nodes = {}) const override;
  // global ← Σ_ranks global at the global dof nodes `nodes` (the cells' supports), where
  // each rank holds its share of a sum (the forces its cells spread); the other entries
  // are left as they are. One MPI_Allreduce of 4 values per node.
  void sum_at_nodes(const Vector& global, const Kokkos::View<const int*>& nodes) const override;
  // The union of every rank's `nodes` (global dof nodes: the supports of the cells each
  // rank transfers), ascending, the same on every rank, as replicate() and sum_at_nodes()
  // need: one MPI_Allreduce of a bit per global dof node. A view of a buffer the next call
  // overwrites.
  Kokkos::View<const int*> nodes_of_any_rank(const Kokkos::View<const int*>& nodes) const override;
  // local ← global at every local dof node, owned and copies.
  void localize(const ConstVector& global, const Vector& local) const override;
  // The local dof node of a global one, or −1 when the rank holds none.
  int local_node(int global_node) const override { return local_of_global_[global_node]; }

  // Point-block Jacobi across the ranks (the same iterates as one rank), or additive
  // Schwarz with ILU(0) or the multigrid per rank.
  std::unique_ptr<FluidPreconditioner> make_preconditioner(const SolverConfig& solver,
                                                           const std::vector<int>& owned_dirichlet) const override;

  // The rank holding each point [μm] (a cell's centroid): the owner of the fluid
  // dof node nearest to it (minimum image in periodic directions; the lowest such rank on
  // ties), the same on every rank. A point farther than any element's diameter from every
  // node (outside the fluid) goes to rank 0. One MPI_Allreduce; all ranks call it together.
  std::vector<int> rank_holding(const std::vector<std::array<double, 3>>& points) const;

 private:
  Communicator communicator_;
  ElementPartition partition_;
  FluidMesh local_mesh_;
  NodeHalo halo_;
  NodeSums node_sums_;
  std::vector<int> local_of_global_;
  // rank_holding(): the owned dof nodes' geometric nodes (a periodic dof node's every
  // image), binned on the host in bins of the mesh's largest element diameter.
  Kokkos::View<double* [3], Kokkos::HostSpace> owned_node_positions_;
  BinnedPoints<Kokkos::HostSpace> owned_node_bins_;
  double largest_element_diameter_ = 0.0;
  Kokkos::View<int*> global_node_;  // local dof node → global dof node (device)
  Kokkos::View<int*> owned_local_;  // global dof node → its local node where this rank owns it, else −1 (device)
  mutable Vector node_buffer_;      // replicate() at some nodes
  // nodes_of_any_rank(): one bit per global dof node (device and host), and the list.
  mutable Kokkos::View<unsigned*> node_bits_;
  mutable Kokkos::View<unsigned*, Kokkos::HostSpace> host_node_bits_;
  mutable Kokkos::View<int*> nodes_of_any_rank_;
  mutable Kokkos::View<double*, Kokkos::HostSpace> host_buffer_;
  // The first 4·nodes entries of a persistent device buffer.
  Vector node_buffer(int nodes) const;
  // replicate() at the global dof nodes `nodes`.
  void replicate_at(const ConstVector& local, const Vector& global, const Kokkos::View<const int*>& nodes) const;
  // Sums `values` over all ranks in place, through host memory.
  void sum_over_ranks(const Vector& values) const;
};

}  // namespace rouleau
