// The optical-tweezers contact patches and the stretched cell's diameters
// (cells/stretch_patches.hpp).
#include "cells/stretch_patches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "util/instantiate.hpp"

namespace rouleau {

template <class ExecSpace>
BasicStretchPatches<ExecSpace>::BasicStretchPatches(const BasicCellPopulation<ExecSpace>& cells, int cell,
                                                    std::array<double, 3> direction,
                                                    std::array<double, 3> in_plane_transverse, double contact_diameter)
    : cell_(cell), transverse_(in_plane_transverse) {
  if (cell < 0 || cell >= cells.num_cells())
    throw std::invalid_argument("rouleau::StretchPatches: no cell " + std::to_string(cell));
  if (!(contact_diameter > 0.0)) throw std::invalid_argument("rouleau::StretchPatches: contact diameter must be > 0");
  const double length =
      std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  if (!(length > 0.0)) throw std::invalid_argument("rouleau::StretchPatches: zero direction");
  for (double& d : direction) d /= length;

  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.positions());
  auto area = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.surface_area_weights());
  const int first = cells.cell_first_node()[cell];
  const int count = cells.cell_node_count()[cell];
  const std::array<double, 3> centroid = cells.measures()[cell].centroid;

  // The ends: the centroid moved along ±direction to the extreme node projections.
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (int a = first; a < first + count; ++a) {
    double s = 0.0;
    for (int i = 0; i < 3; ++i) s += (x(a, i) - centroid[i]) * direction[i];
    lowest = std::min(lowest, s);
    highest = std::max(highest, s);
  }
  std::array<double, 3> end_positive, end_negative;
  for (int i = 0; i < 3; ++i) {
    end_positive[i] = centroid[i] + highest * direction[i];
    end_negative[i] = centroid[i] + lowest * direction[i];
  }
  const double radius2 = 0.25 * contact_diameter * contact_diameter;
  signed_weights_ = Kokkos::View<double*>("rouleau::StretchPatches::signed_weights", cells.num_nodes());
  auto weights = Kokkos::create_mirror_view(signed_weights_);
  Kokkos::deep_copy(weights, 0.0);
  for (int a = first; a < first + count; ++a) {
    if (!(area(a) > 0.0)) continue;  // not on the outer surface
    ++surface_nodes_;
    double d_positive = 0.0, d_negative = 0.0;
    for (int i = 0; i < 3; ++i) {
      d_positive += (x(a, i) - end_positive[i]) * (x(a, i) - end_positive[i]);
      d_negative += (x(a, i) - end_negative[i]) * (x(a, i) - end_negative[i]);
    }
    if (d_positive <= radius2) {
      weights(a) = area(a);
      positive_area_ += area(a);
      ++positive_nodes_;
    } else if (d_negative <= radius2) {
      weights(a) = -area(a);
      negative_area_ += area(a);
      ++negative_nodes_;
    }
  }
  if (positive_nodes_ == 0 || negative_nodes_ == 0)
    throw std::runtime_error(
        "rouleau::StretchPatches: an end patch holds no surface node (contact diameter too small "
        "for the mesh?)");
  for (int a = first; a < first + count; ++a) weights(a) /= weights(a) > 0.0 ? positive_area_ : negative_area_;
  Kokkos::deep_copy(signed_weights_, weights);
}

template <class ExecSpace>
StretchDiameters BasicStretchPatches<ExecSpace>::diameters(const BasicCellPopulation<ExecSpace>& cells) const {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cells.positions());
  auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), signed_weights_);
  const int first = cells.cell_first_node()[cell_];
  const int count = cells.cell_node_count()[cell_];
  StretchDiameters result;
  // Pull direction d̂ = p/|p|, p = Σ w_a x_a; transverse t̂ = the given in-plane direction
  // made perpendicular to d̂.
  std::array<double, 3> p{0.0, 0.0, 0.0};
  for (int a = first; a < first + count; ++a)
    for (int i = 0; i < 3; ++i) p[i] += w(a) * x(a, i);
  const double p_length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  for (int i = 0; i < 3; ++i) result.pull_direction[i] = p[i] / p_length;
  const auto& d = result.pull_direction;
  const double along = transverse_[0] * d[0] + transverse_[1] * d[1] + transverse_[2] * d[2];
  std::array<double, 3> t;
  for (int i = 0; i < 3; ++i) t[i] = transverse_[i] - along * d[i];
  const double t_length = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  for (double& ti : t) ti /= t_length;
  double axial_low = std::numeric_limits<double>::infinity(), axial_high = -axial_low;
  double transverse_low = axial_low, transverse_high = axial_high;
  for (int a = first; a < first + count; ++a) {
    const double s = x(a, 0) * d[0] + x(a, 1) * d[1] + x(a, 2) * d[2];
    const double q = x(a, 0) * t[0] + x(a, 1) * t[1] + x(a, 2) * t[2];
    axial_low = std::min(axial_low, s);
    axial_high = std::max(axial_high, s);
    transverse_low = std::min(transverse_low, q);
    transverse_high = std::max(transverse_high, q);
  }
  result.axial = axial_high - axial_low;
  result.transverse = transverse_high - transverse_low;
  return result;
}

ROULEAU_INSTANTIATE_FOR_EXECUTION_SPACES(BasicStretchPatches)

}  // namespace rouleau
