#include "cells/cell_shape.hpp"

#include <algorithm>
#include <cmath>

#include "util/constants.hpp"

namespace rouleau {

std::vector<ShearPlaneShape> shear_plane_shapes(const CellPopulation& population,
                                                const std::vector<CellMeasures>& measures,
                                                const std::vector<double>& membrane_depth) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.positions());
  auto weight = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_area_weights());
  auto triangles = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_triangles());
  auto triangle_cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.triangle_cell());
  const int cells = population.num_cells();
  // The mean outer-surface edge of each cell (current positions), for the slab.
  std::vector<double> edge_sum(cells, 0.0), edge_count(cells, 0.0);
  for (std::size_t t = 0; t < triangles.extent(0); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = triangles(t, k), b = triangles(t, (k + 1) % 3);
      edge_sum[triangle_cell(t)] += std::hypot(x(a, 0) - x(b, 0), x(a, 1) - x(b, 1), x(a, 2) - x(b, 2));
      edge_count[triangle_cell(t)] += 1.0;
    }
  std::vector<ShearPlaneShape> shapes(cells);
  for (int c = 0; c < cells; ++c) {
    const auto& centroid = measures[c].centroid;
    const double slab = 0.6 * edge_sum[c] / std::max(1.0, edge_count[c]);
    double gxx = 0.0, gxy = 0.0, gyy = 0.0, largest = 0.0, smallest = HUGE_VAL;
    double lowest[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, highest[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    double radius_front = 0.0, radius_rear = 0.0;
    const int first = population.cell_first_node()[c], count = population.cell_node_count()[c];
    for (int n = first; n < first + count; ++n) {
      if (weight(n) <= 0.0) continue;  // not on the outer surface
      for (int d = 0; d < 3; ++d) {
        lowest[d] = std::min(lowest[d], x(n, d));
        highest[d] = std::max(highest[d], x(n, d));
      }
      const double rx = x(n, 0) - centroid[0], ry = x(n, 1) - centroid[1];
      // R = √((y − y_c)² + (z − z_c)²), the distance from the line along x through the centroid
      const double radial = std::hypot(ry, x(n, 2) - centroid[2]);
      double& half = rx > 0.0 ? radius_front : radius_rear;
      half = std::max(half, radial);
      gxx += weight(n) * rx * rx;
      gxy += weight(n) * rx * ry;
      gyy += weight(n) * ry * ry;
      if (std::fabs(x(n, 2) - centroid[2]) < slab) {
        const double r = std::hypot(rx, ry);
        largest = std::max(largest, r);
        smallest = std::min(smallest, r);
      }
    }
    // The major axis of [[gxx, gxy], [gxy, gyy]] is at θ = ½ atan2(2 gxy, gxx − gyy).
    ShearPlaneShape& shape = shapes[c];
    shape.inclination_deg = 0.5 * std::atan2(2.0 * gxy, gxx - gyy) * 180.0 / pi;
    for (int d = 0; d < 3; ++d) shape.extent[d] = highest[d] > lowest[d] ? highest[d] - lowest[d] : 0.0;
    shape.radius_front = radius_front;
    shape.radius_rear = radius_rear;
    if (largest > 0.0) {
      const double depth = membrane_depth.empty() ? 0.0 : membrane_depth.at(c);
      shape.length = largest - depth;
      shape.breadth = smallest - depth;
      shape.taylor_deformation = (shape.length - shape.breadth) / (shape.length + shape.breadth);
    }
  }
  return shapes;
}

}  // namespace rouleau
