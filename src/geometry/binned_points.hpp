#pragma once
// A fixed set of points in bins of a box, for the question "how far is the nearest of them
// from x, if it is within `radius`?" (which rank holds a cell's centroid: the rank owning
// the fluid node nearest to it, FluidDistribution::rank_holding). The bins are cubes of side
// at least `radius` over the box, so the 27 bins around x hold every point within `radius`
// of it. Periodic directions wrap the bins and measure the minimum image.
// Host-only: includes no Kokkos header.
#include <array>
#include <vector>

namespace rouleau {

class BinnedPoints {
 public:
  // `points` [μm] in the box [lower, upper] (a periodic direction's points may sit on either
  // side of it). Throws std::invalid_argument when radius ≤ 0 or the box is empty.
  BinnedPoints(const std::vector<std::array<double, 3>>& points, const std::array<double, 3>& lower,
               const std::array<double, 3>& upper, const std::array<bool, 3>& periodic, double radius);

  // min_p |x − p| over the points within `radius` of x (minimum image in periodic
  // directions), or +∞ when there are none.
  double nearest_distance(const std::array<double, 3>& x) const;

  int size() const { return static_cast<int>(points_.size()); }

 private:
  // Bin coordinate of x along d: wrapped in periodic directions, clamped to the box otherwise.
  int bin_coordinate(double x, int d) const;

  std::vector<std::array<double, 3>> points_;  // sorted by bin
  std::vector<int> bin_offsets_;               // points of bin b: [bin_offsets_[b], bin_offsets_[b + 1])
  std::array<double, 3> lower_{}, length_{}, bin_size_{};
  std::array<int, 3> bins_{};
  std::array<bool, 3> periodic_{};
  double radius_ = 0.0;
};

}  // namespace rouleau
