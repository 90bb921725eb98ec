#pragma once
// The broad phase of rouleau's searches between cells: which axis-aligned boxes meet. The
// case's placement check asks it of the cells' bounding spheres before it tests their
// shapes (config/cell_placement_check), the Morse neighbour list of the cells' bounding
// boxes, no farther apart than the search radius, before it bins their surface points
// (cells/surface_neighbor_list). Host-only: includes no Kokkos header.
#include <array>
#include <utility>
#include <vector>

namespace rouleau {

// An axis-aligned box: {lower x, y, z, upper x, y, z} [μm]. A box with lower > upper (an
// empty one) meets none.
using Box = std::array<double, 6>;

// The pairs (i, j), i < j, ascending, of boxes at most `gap` apart along every direction
// (gap 0: the boxes that meet or touch). By sweep and prune along x: the boxes sorted by
// lower x (ties by index), each compared with the next ones until their lower x passes its
// upper x + gap; O(N log N + K) for K pairs.
std::vector<std::pair<int, int>> boxes_within(const std::vector<Box>& boxes, double gap);

}  // namespace rouleau
