#include "distributed/additive_schwarz.hpp"

#include "distributed/distributed_fluid_operator.hpp"
#include "util/view_transfer.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;

// The CRS position of entry (i, j) of the block of node A's k-th neighbour (fluid_matrix.hpp):
// 16 offsets(A) + 4 deg(A) i + 4 k + j.
std::size_t block_entry(const std::vector<int>& offsets, int node, int k, int i, int j) {
  const int degree = offsets[node + 1] - offsets[node];
  return 16 * static_cast<std::size_t>(offsets[node]) + 4 * static_cast<std::size_t>(degree) * i + 4 * k + j;
}

// Between a matrix's node diagonal blocks (where(n): the block's first entry, rows of
// row_map's length) and a node-major array of 4×4 blocks: blocks ← matrix, or back.
enum class BlockCopy { matrix_to_blocks, blocks_to_matrix };
void copy_diagonal_blocks(const BlockCopy direction, const Kokkos::View<std::size_t*>& where,
                          const Kokkos::View<std::size_t*>& row_map, const Vector& values, const Vector& blocks) {
  const bool to_blocks = direction == BlockCopy::matrix_to_blocks;
  Kokkos::parallel_for(
      "rouleau::AdditiveSchwarz::diagonal_blocks", Kokkos::RangePolicy<ExecSpace>(0, where.extent(0)),
      KOKKOS_LAMBDA(const int n) {
        const std::size_t row_length = row_map(4 * n + 1) - row_map(4 * n);
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) {
            double& in_matrix = values(where(n) + row_length * i + j);
            double& in_blocks = blocks(16 * n + 4 * i + j);
            if (to_blocks)
              in_blocks = in_matrix;
            else
              in_matrix = in_blocks;
          }
      });
}

// The owned block: owned(e) = local(source(e)).
void fill_owned_block(const Kokkos::View<std::size_t*>& source, const Vector& local, const Vector& owned) {
  Kokkos::parallel_for(
      "rouleau::AdditiveSchwarz::owned_block", Kokkos::RangePolicy<ExecSpace>(0, source.extent(0)),
      KOKKOS_LAMBDA(const int e) { owned(e) = local(source(e)); });
}
// The strength graph of the rank's mesh (fluid_node_strength) between its owned nodes.
WeightedGraph owned_strength(const FluidMesh& local_mesh, const int owned_nodes) {
  const WeightedGraph local = fluid_node_strength(local_mesh);
  WeightedGraph owned;
  owned.offsets.push_back(0);
  for (int a = 0; a < owned_nodes; ++a) {
    for (int k = local.offsets[a]; k < local.offsets[a + 1]; ++k)
      if (local.neighbors[k] < owned_nodes) {
        owned.neighbors.push_back(local.neighbors[k]);
        owned.weights.push_back(local.weights[k]);
      }
    owned.offsets.push_back(static_cast<int>(owned.neighbors.size()));
  }
  return owned;
}
}  // namespace

AdditiveSchwarz::AdditiveSchwarz(const Communicator& communicator, const ElementPartition& partition,
                                 const FluidMesh& local_mesh, const std::vector<int>& dirichlet,
                                 const SubdomainSolver solver, const AggregationMultigridSettings& multigrid)
    : owned_nodes_(partition.num_owned_nodes),
      local_graph_(build_fluid_matrix_graph(local_mesh)),
      block_halo_(communicator, partition, 16),
      dirichlet_(device_copy(dirichlet, "rouleau::AdditiveSchwarz::dirichlet")) {
  // The owned × owned node graph, and where each of its entries sits in the local graph.
  auto offsets_view = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), local_graph_.node_offsets);
  auto neighbors_view = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), local_graph_.node_neighbors);
  const std::vector<int> local_offsets(offsets_view.data(), offsets_view.data() + offsets_view.extent(0));
  std::vector<int> owned_offsets{0}, owned_neighbors;
  std::vector<std::vector<int>> kept(owned_nodes_);  // local neighbour indices k kept per owned node
  for (int a = 0; a < owned_nodes_; ++a) {
    for (int k = 0; k < local_offsets[a + 1] - local_offsets[a]; ++k) {
      const int b = neighbors_view(local_offsets[a] + k);
      if (b < owned_nodes_) kept[a].push_back(k), owned_neighbors.push_back(b);
    }
    owned_offsets.push_back(static_cast<int>(owned_neighbors.size()));
  }
  owned_graph_ = make_block_matrix_graph(owned_offsets, owned_neighbors);
  std::vector<std::size_t> source(16 * owned_neighbors.size());
  for (int a = 0; a < owned_nodes_; ++a)
    for (int kk = 0; kk < static_cast<int>(kept[a].size()); ++kk)
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          source[block_entry(owned_offsets, a, kk, i, j)] = block_entry(local_offsets, a, kept[a][kk], i, j);
  owned_entry_source_ = device_copy(source, "rouleau::AdditiveSchwarz::owned_entry_source");
  // Each local node's own block in the local graph.
  std::vector<std::size_t> diagonal(partition.num_local_nodes());
  for (int a = 0; a < partition.num_local_nodes(); ++a)
    for (int k = 0; k < local_offsets[a + 1] - local_offsets[a]; ++k)
      if (neighbors_view(local_offsets[a] + k) == a) diagonal[a] = block_entry(local_offsets, a, k, 0, 0);
  diagonal_block_ = device_copy(diagonal, "rouleau::AdditiveSchwarz::diagonal_block");
  std::vector<std::size_t> owned_diagonal(owned_nodes_);
  for (int a = 0; a < owned_nodes_; ++a)
    for (int k = 0; k < owned_offsets[a + 1] - owned_offsets[a]; ++k)
      if (owned_neighbors[owned_offsets[a] + k] == a) owned_diagonal[a] = block_entry(owned_offsets, a, k, 0, 0);
  owned_diagonal_block_ = device_copy(owned_diagonal, "rouleau::AdditiveSchwarz::owned_diagonal_block");
  local_values_ = Vector("rouleau::AdditiveSchwarz::local_values", local_graph_.entries.extent(0));
  owned_values_ = Vector("rouleau::AdditiveSchwarz::owned_values", owned_graph_.entries.extent(0));
  local_blocks_ = Vector("rouleau::AdditiveSchwarz::local_blocks", 16 * partition.num_local_nodes());
  if (solver == SubdomainSolver::ilu0)
    ilu_ = std::make_unique<Ilu0Preconditioner>(owned_graph_.row_map, owned_graph_.entries);
  else
    multigrid_ =
        std::make_unique<AggregationMultigrid>(owned_graph_, owned_strength(local_mesh, owned_nodes_), multigrid);
}

AdditiveSchwarz::~AdditiveSchwarz() = default;

void AdditiveSchwarz::factor(const FluidOperator& local, const ConstVector& state) {
  require_node_sums(local, "AdditiveSchwarz");  // for the projected gradient of the viscous reconstruction
  local.assemble_jacobian(state, local_graph_, local_values_);
  // the owned nodes' diagonal blocks, with the other ranks' elements added at the owner
  copy_diagonal_blocks(BlockCopy::matrix_to_blocks, diagonal_block_, local_graph_.row_map, local_values_,
                       local_blocks_);
  block_halo_.add_copies_to_owners(local_blocks_);
  fill_owned_block(owned_entry_source_, local_values_, owned_values_);
  // node a's own block in the owned graph, whole
  copy_diagonal_blocks(BlockCopy::blocks_to_matrix, owned_diagonal_block_, owned_graph_.row_map, owned_values_,
                       local_blocks_);
  // then the identity's rows for the constrained unknowns
  set_identity_rows(owned_graph_, dirichlet_, owned_values_);
  if (ilu_)
    ilu_->factor(owned_values_);
  else
    multigrid_->set_values(owned_values_);
}

void AdditiveSchwarz::apply(const Kokkos::View<const double*>& r, const Kokkos::View<double*>& z) const {
  if (ilu_)
    ilu_->apply(r, z);
  else
    multigrid_->apply(r, z);
}

}  // namespace rouleau
