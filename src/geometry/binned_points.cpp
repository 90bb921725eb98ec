#include "geometry/binned_points.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rouleau {

BinnedPoints::BinnedPoints(const std::vector<std::array<double, 3>>& points, const std::array<double, 3>& lower,
                           const std::array<double, 3>& upper, const std::array<bool, 3>& periodic,
                           const double radius)
    : lower_(lower), periodic_(periodic), radius_(radius) {
  if (!(radius > 0.0))
    throw std::invalid_argument("rouleau::BinnedPoints: the radius must be > 0, got " + std::to_string(radius));
  for (int d = 0; d < 3; ++d) {
    length_[d] = upper[d] - lower[d];
    if (!(length_[d] > 0.0)) throw std::invalid_argument("rouleau::BinnedPoints: an empty box");
    // Bins of side ≥ radius (at least one per direction).
    bins_[d] = std::max(1, static_cast<int>(std::floor(length_[d] / radius)));
    bin_size_[d] = length_[d] / bins_[d];
  }
  const int num_bins = bins_[0] * bins_[1] * bins_[2];
  auto bin_of = [&](const std::array<double, 3>& p) {
    return bin_coordinate(p[0], 0) + bins_[0] * (bin_coordinate(p[1], 1) + bins_[1] * bin_coordinate(p[2], 2));
  };
  // Counting sort of the points by bin.
  bin_offsets_.assign(num_bins + 1, 0);
  for (const auto& p : points) ++bin_offsets_[bin_of(p) + 1];
  for (int b = 0; b < num_bins; ++b) bin_offsets_[b + 1] += bin_offsets_[b];
  points_.resize(points.size());
  std::vector<int> next(bin_offsets_.begin(), bin_offsets_.end() - 1);
  for (const auto& p : points) points_[next[bin_of(p)]++] = p;
}

int BinnedPoints::bin_coordinate(const double x, const int d) const {
  const int b = static_cast<int>(std::floor((x - lower_[d]) / bin_size_[d]));
  if (periodic_[d]) return ((b % bins_[d]) + bins_[d]) % bins_[d];
  return std::clamp(b, 0, bins_[d] - 1);
}

double BinnedPoints::nearest_distance(const std::array<double, 3>& x) const {
  double nearest2 = std::numeric_limits<double>::infinity();
  std::array<int, 3> centre{};
  for (int d = 0; d < 3; ++d) centre[d] = bin_coordinate(x[d], d);
  // The 27 bins around x's (fewer where a direction has fewer bins; a bin met twice through
  // the wrap only repeats distances).
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const std::array<int, 3> step{di, dj, dk};
        std::array<int, 3> b{};
        bool inside = true;
        for (int d = 0; d < 3; ++d) {
          b[d] = centre[d] + step[d];
          if (periodic_[d])
            b[d] = (b[d] + bins_[d]) % bins_[d];
          else
            inside = inside && b[d] >= 0 && b[d] < bins_[d];
        }
        if (!inside) continue;
        const int bin = b[0] + bins_[0] * (b[1] + bins_[1] * b[2]);
        for (int p = bin_offsets_[bin]; p < bin_offsets_[bin + 1]; ++p) {
          double distance2 = 0.0;
          for (int d = 0; d < 3; ++d) {
            double offset = x[d] - points_[p][d];
            // the minimum image: |offset| ≤ L/2
            if (periodic_[d]) offset -= length_[d] * std::round(offset / length_[d]);
            distance2 += offset * offset;
          }
          nearest2 = std::min(nearest2, distance2);
        }
      }
  return nearest2 <= radius_ * radius_ ? std::sqrt(nearest2) : std::numeric_limits<double>::infinity();
}

}  // namespace rouleau
