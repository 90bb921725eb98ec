#include "geometry/box_overlaps.hpp"

#include <algorithm>
#include <numeric>

namespace rouleau {

std::vector<std::pair<int, int>> boxes_within(const std::vector<Box>& boxes, const double gap) {
  const int n = static_cast<int>(boxes.size());
  std::vector<int> by_lower_x(n);
  std::iota(by_lower_x.begin(), by_lower_x.end(), 0);
  std::sort(by_lower_x.begin(), by_lower_x.end(), [&](const int a, const int b) {
    return boxes[a][0] < boxes[b][0] || (boxes[a][0] == boxes[b][0] && a < b);
  });
  // Boxes a and b are within the gap where lower_b ≤ upper_a + gap and lower_a ≤ upper_b + gap
  // along every direction.
  std::vector<std::pair<int, int>> pairs;
  for (int a = 0; a < n; ++a) {
    const Box& p = boxes[by_lower_x[a]];
    if (p[0] > p[3]) continue;  // empty
    for (int b = a + 1; b < n; ++b) {
      const Box& q = boxes[by_lower_x[b]];
      if (q[0] > p[3] + gap) break;
      bool meet = true;
      for (int d = 0; d < 3; ++d) meet = meet && q[d] <= p[3 + d] + gap && p[d] <= q[3 + d] + gap;
      if (meet) pairs.emplace_back(std::min(by_lower_x[a], by_lower_x[b]), std::max(by_lower_x[a], by_lower_x[b]));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace rouleau
