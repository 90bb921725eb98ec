#include "cells/rim_band.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace rouleau {

RimBand::RimBand(const CellPopulation& population, double rim_height_fraction) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.reference_positions());
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_area_weights());
  const int nodes = static_cast<int>(x.extent(0));
  in_band_.assign(nodes, 0);
  on_surface_.assign(nodes, 0);
  double band_area = 0.0, area = 0.0;
  for (int c = 0; c < population.num_cells(); ++c) {
    const int first = population.cell_first_node()[c], end = first + population.cell_node_count()[c];
    // The surface's area-weighted centroid and second moment M = Σ w (X − X̄)(X − X̄)ᵀ.
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    double cell_area = 0.0;
    for (int n = first; n < end; ++n) {
      centroid += w(n) * Eigen::Vector3d(x(n, 0), x(n, 1), x(n, 2));
      cell_area += w(n);
    }
    if (cell_area <= 0.0) continue;
    centroid /= cell_area;
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    for (int n = first; n < end; ++n) {
      const Eigen::Vector3d d = Eigen::Vector3d(x(n, 0), x(n, 1), x(n, 2)) - centroid;
      moment += w(n) * d * d.transpose();
    }
    // The eigenvalues come in increasing order: the axis is the first eigenvector.
    const Eigen::Vector3d axis = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(moment).eigenvectors().col(0);
    // z = |d·a|, the height above the mid-plane; its largest over the surface.
    std::vector<double> height(end - first, 0.0);
    double largest = 0.0;
    for (int n = first; n < end; ++n) {
      if (w(n) <= 0.0) continue;
      const Eigen::Vector3d d = Eigen::Vector3d(x(n, 0), x(n, 1), x(n, 2)) - centroid;
      height[n - first] = std::fabs(d.dot(axis));
      largest = std::max(largest, height[n - first]);
    }
    for (int n = first; n < end; ++n) {
      if (w(n) <= 0.0) continue;
      on_surface_[n] = 1;
      area += w(n);
      if (height[n - first] >= rim_height_fraction * largest) {
        in_band_[n] = 1;
        band_area += w(n);
      }
    }
  }
  area_share_ = area > 0.0 ? band_area / area : 0.0;
}

double RimBand::force_share(const double* forces) const {
  double band = 0.0, all = 0.0;
  for (std::size_t n = 0; n < in_band_.size(); ++n) {
    if (!on_surface_[n]) continue;
    const double* f = forces + 3 * n;
    const double magnitude = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    all += magnitude;
    if (in_band_[n]) band += magnitude;
  }
  return all > 0.0 ? band / all : 0.0;
}

}  // namespace rouleau
