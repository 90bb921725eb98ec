#pragma once
// The fluid mesh split across ranks: which rank owns each element, and each
// rank's local view of the dof nodes, with global ids beside local indices.
//
// Elements are owned, nodes shared. A rank holds the dof nodes of its elements; a node
// touched by the elements of several ranks is owned by the lowest of them, and the others
// hold a copy. Local dof nodes are numbered owned first (ascending global id), then the
// copies (ascending global id), so the owned unknowns are a prefix of every local vector
// and a reduction over them needs no mask.
//
// Exchanges go between a node's owner and each rank holding a copy, both sides listing the
// shared nodes in ascending global id:
//   update copies    owner → copies: the owned nodes' values;
//   sum into owners  copies → owner: partial element sums, which the owner adds to its own
//                    in ascending rank order (the result does not depend on arrival order).
// Matrix-free operators need nothing else: each rank sums its elements into its local
// nodes, the partial sums of shared nodes meet at the owner, and the owner's total goes
// back to the copies. Host-only (no Kokkos, no MPI): every rank computes its own partition
// from the global mesh.
#include <array>
#include <vector>

namespace rouleau {

// Ranks per direction p = (p_x, p_y, p_z) with p_x p_y p_z = ranks for a box of `elements`
// per direction: the split that cuts the fewest element faces (the interface area), with
// every p_d ≤ elements_d; among equals, the one that splits x most, then y. Throws
// std::invalid_argument when no split fits (more ranks than elements along the factors).
std::array<int, 3> block_grid(const std::array<int, 3>& elements, int ranks);

// The owner of every element of a structured box (element (i, j, k) at i + n_x (j + n_y k),
// FluidMesh::structured_elements): the blocks of block_grid(elements, ranks), as even as
// integer division allows (block b of p along n elements holds [⌊b n/p⌋, ⌊(b+1) n/p⌋)),
// block (b_x, b_y, b_z) on rank b_x + p_x (b_y + p_y b_z).
std::vector<int> block_element_owners(const std::array<int, 3>& elements, int ranks);

// The owner of every element of an unstructured mesh (Gmsh vessels): a k-way partition of
// the elements' dual graph (elements adjacent when they share a face: `face_nodes` nodes,
// 3 for tetrahedra, 4 for hexahedra) by METIS, with a fixed seed, so every rank computes
// the same partition from the same mesh. Parts are balanced to 3 % of E/ranks. Throws
// std::runtime_error in a build without METIS (ROULEAU_HAS_METIS).
std::vector<int> graph_element_owners(const std::vector<int>& element_dof_nodes, int nodes_per_element,
                                      int num_dof_nodes, int face_nodes, int ranks);
// Whether this build can partition unstructured meshes.
bool has_graph_partitioner();

// The nodes shared with one other rank.
struct NeighborExchange {
  int rank = 0;                   // the other rank
  std::vector<int> owned_shared;  // local nodes this rank owns and `rank` holds copies of
  std::vector<int> copies;        // local nodes `rank` owns and this rank holds copies of
};

struct ElementPartition {
  int rank = 0, num_ranks = 1;
  // Global ids of the elements this rank owns: first the `num_boundary_elements` that touch
  // a node shared with another rank, then the interior ones (no shared node), each group
  // ascending. The rank's mesh keeps this order (make_local_mesh), so its element loops can
  // sum the boundary first and exchange while the interior is summed (NodeSums).
  std::vector<int> elements;
  int num_boundary_elements = 0;
  std::vector<int> global_node;             // local dof node → global dof node
  int num_owned_nodes = 0;                  // local nodes [0, num_owned_nodes) are owned
  std::vector<int> node_owner;              // local dof node → its owner's rank
  std::vector<NeighborExchange> neighbors;  // ascending rank
  int num_global_nodes = 0;

  int num_local_nodes() const { return static_cast<int>(global_node.size()); }
};

// Rank `rank`'s partition, from every element's owner and the global element → dof node
// connectivity (row-major: element e's nodes at [e·nodes_per_element, (e+1)·nodes_per_element)).
// Throws std::invalid_argument on an owner outside [0, num_ranks) or a node out of range.
ElementPartition make_element_partition(int rank, int num_ranks, const std::vector<int>& element_owner,
                                        const std::vector<int>& element_dof_nodes, int nodes_per_element,
                                        int num_dof_nodes);

}  // namespace rouleau
