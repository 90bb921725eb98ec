#pragma once
// Aggregation of a weighted node graph by repeated pairwise matching (the coarsening of
// Notay's aggregation multigrid, "AGMG", Notay 2010, with the matrix's strength replaced by
// a geometric one): each pass visits the nodes in order of increasing degree and pairs a
// node with its unmatched neighbour of largest weight (a node with none stays single);
// the pairs become nodes of a graph whose edge weights are the sums of their members'
// weights, and the next pass matches that graph. Three passes give aggregates of up to 8
// nodes, the 2×2×2 blocks of a structured box.
//
// Host code: the hierarchy is built once per mesh (the fluid mesh never moves), so it is
// deterministic and a restarted run coarsens exactly as the straight one did.
#include <vector>

namespace rouleau {

// A symmetric weighted graph in CSR form without self-edges.
struct WeightedGraph {
  std::vector<int> offsets;     // num_nodes + 1
  std::vector<int> neighbors;   // sorted within each node
  std::vector<double> weights;  // beside neighbors
  int num_nodes() const { return static_cast<int>(offsets.size()) - 1; }
};

struct Aggregation {
  std::vector<int> aggregate_of;  // node -> aggregate
  int num_aggregates = 0;
  WeightedGraph coarse_graph;     // the aggregates' graph (weights summed)
};

// `passes` rounds of pairwise matching.
Aggregation aggregate_pairwise(const WeightedGraph& graph, int passes);

// The graph of the aggregates: weight(I, J) = Σ_{a∈I, b∈J} weight(a, b), I ≠ J.
WeightedGraph coarsen_graph(const WeightedGraph& graph, const std::vector<int>& aggregate_of, int num_aggregates);

}  // namespace rouleau
