#include "host_algebra/pairwise_aggregation.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

namespace rouleau {

namespace {

// One matching pass: node -> pair index.
std::vector<int> match_pairs(const WeightedGraph& graph, int& num_pairs) {
  const int n = graph.num_nodes();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  // Nodes with few neighbours (corners, walls) first, so they find a partner.
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return graph.offsets[a + 1] - graph.offsets[a] < graph.offsets[b + 1] - graph.offsets[b];
  });
  std::vector<int> pair_of(n, -1);
  num_pairs = 0;
  for (int node : order) {
    if (pair_of[node] >= 0) continue;
    int partner = -1;
    double strongest = 0.0;
    for (int k = graph.offsets[node]; k < graph.offsets[node + 1]; ++k) {
      const int other = graph.neighbors[k];
      if (pair_of[other] < 0 && graph.weights[k] > strongest) {
        strongest = graph.weights[k];
        partner = other;
      }
    }
    pair_of[node] = num_pairs;
    if (partner >= 0) pair_of[partner] = num_pairs;
    ++num_pairs;
  }
  return pair_of;
}

}  // namespace

WeightedGraph coarsen_graph(const WeightedGraph& graph, const std::vector<int>& aggregate_of, int num_aggregates) {
  std::vector<std::vector<std::pair<int, double>>> edges(num_aggregates);
  for (int a = 0; a < graph.num_nodes(); ++a)
    for (int k = graph.offsets[a]; k < graph.offsets[a + 1]; ++k) {
      const int I = aggregate_of[a], J = aggregate_of[graph.neighbors[k]];
      if (I != J) edges[I].emplace_back(J, graph.weights[k]);
    }
  WeightedGraph coarse;
  coarse.offsets.assign(num_aggregates + 1, 0);
  for (int I = 0; I < num_aggregates; ++I) {
    auto& list = edges[I];
    std::sort(list.begin(), list.end());
    // Merge repeated neighbours, summing their weights.
    std::size_t merged = 0;
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (merged > 0 && list[merged - 1].first == list[k].first)
        list[merged - 1].second += list[k].second;
      else
        list[merged++] = list[k];
    }
    list.resize(merged);
    coarse.offsets[I + 1] = coarse.offsets[I] + static_cast<int>(merged);
    for (const auto& [J, w] : list) {
      coarse.neighbors.push_back(J);
      coarse.weights.push_back(w);
    }
  }
  return coarse;
}

Aggregation aggregate_pairwise(const WeightedGraph& graph, int passes) {
  Aggregation result;
  result.aggregate_of.resize(graph.num_nodes());
  std::iota(result.aggregate_of.begin(), result.aggregate_of.end(), 0);
  result.num_aggregates = graph.num_nodes();
  result.coarse_graph = graph;
  for (int pass = 0; pass < passes; ++pass) {
    int num_pairs = 0;
    const std::vector<int> pair_of = match_pairs(result.coarse_graph, num_pairs);
    for (int& aggregate : result.aggregate_of) aggregate = pair_of[aggregate];
    result.coarse_graph = coarsen_graph(result.coarse_graph, pair_of, num_pairs);
    result.num_aggregates = num_pairs;
  }
  return result;
}

}  // namespace rouleau
