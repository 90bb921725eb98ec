#include "parallel/element_partition.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#if ROULEAU_HAS_METIS
#include <metis.h>
#endif

namespace rouleau {

std::array<int, 3> block_grid(const std::array<int, 3>& elements, int ranks) {
  if (ranks < 1) throw std::invalid_argument("rouleau::block_grid: ranks must be >= 1, got " + std::to_string(ranks));
  std::array<int, 3> best{0, 0, 0};
  long long best_cut = std::numeric_limits<long long>::max();
  const long long n[3] = {elements[0], elements[1], elements[2]};
  for (int px = ranks; px >= 1; --px) {
    if (ranks % px != 0 || px > n[0]) continue;
    for (int py = ranks / px; py >= 1; --py) {
      if ((ranks / px) % py != 0 || py > n[1]) continue;
      const int pz = ranks / px / py;
      if (pz > n[2]) continue;
      // element faces cut by the interior interfaces
      const long long cut = (px - 1) * n[1] * n[2] + (py - 1) * n[0] * n[2] + (pz - 1) * n[0] * n[1];
      if (cut < best_cut) best_cut = cut, best = {px, py, pz};
    }
  }
  if (best_cut == std::numeric_limits<long long>::max())
    throw std::invalid_argument("rouleau::block_grid: " + std::to_string(ranks) + " ranks do not split a box of " +
                                std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " + std::to_string(n[2]) +
                                " elements into blocks of at least one element");
  return best;
}

std::vector<int> block_element_owners(const std::array<int, 3>& elements, int ranks) {
  const std::array<int, 3> p = block_grid(elements, ranks);
  // block of index i along n elements split p ways: the b with ⌊b n/p⌋ ≤ i < ⌊(b+1) n/p⌋
  std::array<std::vector<int>, 3> block_of;
  for (int d = 0; d < 3; ++d) {
    block_of[d].resize(elements[d]);
    for (int b = 0; b < p[d]; ++b)
      for (long long i = static_cast<long long>(b) * elements[d] / p[d];
           i < static_cast<long long>(b + 1) * elements[d] / p[d]; ++i)
        block_of[d][i] = b;
  }
  std::vector<int> owner(static_cast<std::size_t>(elements[0]) * elements[1] * elements[2]);
  for (int k = 0; k < elements[2]; ++k)
    for (int j = 0; j < elements[1]; ++j)
      for (int i = 0; i < elements[0]; ++i)
        owner[i + static_cast<std::size_t>(elements[0]) * (j + static_cast<std::size_t>(elements[1]) * k)] =
            block_of[0][i] + p[0] * (block_of[1][j] + p[1] * block_of[2][k]);
  return owner;
}

#if ROULEAU_HAS_METIS
bool has_graph_partitioner() { return true; }

std::vector<int> graph_element_owners(const std::vector<int>& element_dof_nodes, int nodes_per_element,
                                      int num_dof_nodes, int face_nodes, int ranks) {
  const std::string where = "rouleau::graph_element_owners: ";
  if (ranks < 1) throw std::invalid_argument(where + "ranks must be >= 1, got " + std::to_string(ranks));
  idx_t elements = static_cast<idx_t>(element_dof_nodes.size() / nodes_per_element);
  std::vector<int> owner(elements, 0);
  if (ranks == 1) return owner;
  if (ranks > elements)
    throw std::invalid_argument(where + std::to_string(ranks) + " ranks for " + std::to_string(elements) + " elements");
  idx_t nodes = num_dof_nodes, common = face_nodes, parts = ranks, cut = 0;
  std::vector<idx_t> offsets(elements + 1), connectivity(element_dof_nodes.begin(), element_dof_nodes.end());
  for (idx_t e = 0; e <= elements; ++e) offsets[e] = e * nodes_per_element;
  std::vector<idx_t> element_part(elements), node_part(num_dof_nodes);
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 20041;  // the same partition on every rank and every run
  options[METIS_OPTION_UFACTOR] = 30;  // parts within 3 % of the mean
  const int status = METIS_PartMeshDual(&elements, &nodes, offsets.data(), connectivity.data(), nullptr, nullptr,
                                        &common, &parts, nullptr, options, &cut, element_part.data(),
                                        node_part.data());
  if (status != METIS_OK)
    throw std::runtime_error(where + "METIS_PartMeshDual failed (status " + std::to_string(status) + ")");
  for (idx_t e = 0; e < elements; ++e) owner[e] = static_cast<int>(element_part[e]);
  return owner;
}
#else
bool has_graph_partitioner() { return false; }

std::vector<int> graph_element_owners(const std::vector<int>&, int, int, int, int) {
  throw std::runtime_error(
      "rouleau::graph_element_owners: this build has no METIS (Debian: libmetis-dev) to partition an unstructured "
      "mesh");
}
#endif

ElementPartition make_element_partition(int rank, int num_ranks, const std::vector<int>& element_owner,
                                        const std::vector<int>& element_dof_nodes, int nodes_per_element,
                                        int num_dof_nodes) {
  const std::string where = "rouleau::make_element_partition: ";
  if (num_ranks < 1 || rank < 0 || rank >= num_ranks)
    throw std::invalid_argument(where + "rank " + std::to_string(rank) + " of " + std::to_string(num_ranks));
  const std::size_t num_elements = element_owner.size();
  if (element_dof_nodes.size() != num_elements * nodes_per_element)
    throw std::invalid_argument(where + "the connectivity does not hold nodes_per_element nodes per element");
  ElementPartition p;
  p.rank = rank;
  p.num_ranks = num_ranks;
  p.num_global_nodes = num_dof_nodes;

  // Each node's owner (the lowest rank touching it) and whether this rank touches it.
  std::vector<int> owner(num_dof_nodes, num_ranks);
  std::vector<char> mine(num_dof_nodes, 0);
  for (std::size_t e = 0; e < num_elements; ++e) {
    const int r = element_owner[e];
    if (r < 0 || r >= num_ranks)
      throw std::invalid_argument(where + "element " + std::to_string(e) + " has owner " + std::to_string(r));
    if (r == rank) p.elements.push_back(static_cast<int>(e));
    for (int a = 0; a < nodes_per_element; ++a) {
      const int n = element_dof_nodes[e * nodes_per_element + a];
      if (n < 0 || n >= num_dof_nodes)
        throw std::invalid_argument(where + "element " + std::to_string(e) + " names node " + std::to_string(n));
      owner[n] = std::min(owner[n], r);
      if (r == rank) mine[n] = 1;
    }
  }

  // Local numbering: owned nodes, then copies, each in ascending global id.
  std::vector<int> local(num_dof_nodes, -1);
  for (int n = 0; n < num_dof_nodes; ++n)
    if (mine[n] && owner[n] == rank) local[n] = static_cast<int>(p.global_node.size()), p.global_node.push_back(n);
  p.num_owned_nodes = static_cast<int>(p.global_node.size());
  for (int n = 0; n < num_dof_nodes; ++n)
    if (mine[n] && owner[n] != rank) local[n] = static_cast<int>(p.global_node.size()), p.global_node.push_back(n);
  for (const int n : p.global_node) p.node_owner.push_back(owner[n]);

  // The other ranks touching each of this rank's nodes: those holding copies of the nodes
  // it owns. (The copies it holds are shared with their owner alone.)
  std::vector<std::vector<int>> copied_by(p.num_owned_nodes);
  for (std::size_t e = 0; e < num_elements; ++e) {
    const int r = element_owner[e];
    if (r == rank) continue;
    for (int a = 0; a < nodes_per_element; ++a) {
      const int n = element_dof_nodes[e * nodes_per_element + a];
      if (mine[n] && owner[n] == rank) {
        std::vector<int>& ranks = copied_by[local[n]];
        if (std::find(ranks.begin(), ranks.end(), r) == ranks.end()) ranks.push_back(r);
      }
    }
  }
  std::vector<NeighborExchange> by_rank(num_ranks);
  // In ascending local index, which within owned nodes and within copies is ascending global id.
  for (int l = 0; l < p.num_owned_nodes; ++l)
    for (const int r : copied_by[l]) by_rank[r].owned_shared.push_back(l);
  for (int l = p.num_owned_nodes; l < p.num_local_nodes(); ++l) by_rank[p.node_owner[l]].copies.push_back(l);
  for (int r = 0; r < num_ranks; ++r)
    if (!by_rank[r].owned_shared.empty() || !by_rank[r].copies.empty()) {
      by_rank[r].rank = r;
      p.neighbors.push_back(std::move(by_rank[r]));
    }

  // Boundary elements (touching a shared node: a copy, or an owned node others copy) first.
  const auto touches_shared = [&](int e) {
    for (int a = 0; a < nodes_per_element; ++a) {
      const int l = local[element_dof_nodes[e * nodes_per_element + a]];
      if (l >= p.num_owned_nodes || !copied_by[l].empty()) return true;
    }
    return false;
  };
  const auto interior = std::stable_partition(p.elements.begin(), p.elements.end(), touches_shared);
  p.num_boundary_elements = static_cast<int>(interior - p.elements.begin());
  return p;
}

}  // namespace rouleau
