#include "coupling/film_drainage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "cells/film_lubrication.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
// A node's gap is taken as at least this [μm] in Reynolds' equation: surfaces that touch
// or overlap leave a film of molecular size, not none.
constexpr double least_gap = 1e-3;
}  // namespace

FilmDrainage::FilmDrainage(const CellPopulation& population, double open_gap, double viscosity)
    : population_(population),
      open_gap_(open_gap),
      viscosity_(viscosity),
      gaps_(population, open_gap),
      cell_velocity_("rouleau::FilmDrainage::cell_velocity", population.num_cells()) {
  if (!(open_gap > 0.0)) throw std::invalid_argument("rouleau::FilmDrainage: the open gap must be > 0");
  auto triangle_cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.triangle_cell());
  const auto triangles = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_triangles());
  for (std::size_t t = 0; t < triangles.extent(0); ++t)
    triangles_.push_back({triangles(t, 0), triangles(t, 1), triangles(t, 2)});
  cell_triangles_.assign(population.num_cells(), {});
  for (std::size_t t = 0; t < triangle_cell.extent(0); ++t) cell_triangles_[triangle_cell(t)].push_back(int(t));
}

void FilmDrainage::add_opening_velocities(CellPopulation::ConstNodeVectors felt_forces,
                                          CellPopulation::ConstNodeVectors interpolated,
                                          CellPopulation::NodeVectors velocities, double dt,
                                          double velocity_scale) {
  ProfilingRegion region("rouleau::FilmDrainage::add_opening_velocities");
  const int cells = population_.num_cells();
  const auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population_.positions());
  const auto f = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), felt_forces);
  const auto& first = population_.cell_first_node();
  const auto& count = population_.cell_node_count();
  // Each cell's centroid (of its nodes) and the radius of a sphere about it that holds it.
  std::vector<std::array<double, 3>> centroid(cells, {0.0, 0.0, 0.0});
  std::vector<double> radius(cells, 0.0);
  for (int c = 0; c < cells; ++c) {
    for (int n = first[c]; n < first[c] + count[c]; ++n)
      for (int i = 0; i < 3; ++i) centroid[c][i] += x(n, i) / count[c];
    for (int n = first[c]; n < first[c] + count[c]; ++n)
      radius[c] = std::max(radius[c], std::hypot(x(n, 0) - centroid[c][0], x(n, 1) - centroid[c][1],
                                                 x(n, 2) - centroid[c][2]));
  }
  // Cell c's film patch: its outer-surface triangles whose nodes are all within twice the
  // open gap of the other cell (distance[k] for c's node first[c] + k).
  const auto patch = [&](int c, const std::vector<double>& distance) {
    FilmPatch film;
    std::vector<int> local(count[c], -1);
    for (const int t : cell_triangles_[c]) {
      bool near = true;
      for (int k = 0; k < 3; ++k) near = near && distance[triangles_[t][k] - first[c]] < 2.0 * open_gap_;
      if (!near) continue;
      std::array<int, 3> corners{};
      for (int k = 0; k < 3; ++k) {
        const int node = triangles_[t][k], j = node - first[c];
        if (local[j] < 0) {
          local[j] = static_cast<int>(film.points.size());
          film.points.push_back({x(node, 0), x(node, 1), x(node, 2)});
          film.gap.push_back(std::max(distance[j], least_gap));
        }
        corners[k] = local[j];
      }
      film.triangles.push_back(corners);
    }
    return film;
  };
  // T_c = −Σ f_i · n over c's nodes inside the film, n pointing to the other cell.
  const auto load = [&](int c, const std::vector<double>& distance, const std::array<double, 3>& n) {
    double sum = 0.0;
    for (int k = 0; k < count[c]; ++k)
      if (distance[k] < open_gap_) {
        const int node = first[c] + k;
        sum -= f(node, 0) * n[0] + f(node, 1) * n[1] + f(node, 2) * n[2];
      }
    return sum;
  };

  films_.clear();
  std::vector<std::array<double, 3>> normals;  // per film, n from a to b
  gaps_.locate_surfaces();
  for (int a = 0; a < cells; ++a)
    for (int b = a + 1; b < cells; ++b) {
      std::array<double, 3> n{centroid[b][0] - centroid[a][0], centroid[b][1] - centroid[a][1],
                              centroid[b][2] - centroid[a][2]};
      const double separation = std::hypot(n[0], n[1], n[2]);
      if (separation > radius[a] + radius[b] + open_gap_ || separation <= 0.0) continue;
      for (double& component : n) component /= separation;
      const std::vector<double> from_a = gaps_.node_distances_to(a, b);
      const double smallest_gap = *std::min_element(from_a.begin(), from_a.end());
      if (!(smallest_gap < open_gap_)) continue;
      const std::vector<double> from_b = gaps_.node_distances_to(b, a);
      Film film{a, b, smallest_gap};
      const std::array<double, 3> reversed{-n[0], -n[1], -n[2]};
      film.load = 0.5 * (load(a, from_a, n) + load(b, from_b, reversed));
      const double resistance_a = squeeze_resistance(patch(a, from_a), viscosity_, open_gap_);
      const double resistance_b = squeeze_resistance(patch(b, from_b), viscosity_, open_gap_);
      film.resistance = resistance_a > 0.0 && resistance_b > 0.0 ? 0.5 * (resistance_a + resistance_b)
                                                                 : std::max(resistance_a, resistance_b);
      if (film.resistance > 0.0) {
        const double fade = (1.0 - smallest_gap / open_gap_) * (1.0 - smallest_gap / open_gap_);
        const double limit = 0.25 * smallest_gap / dt;
        film.opening_speed = std::clamp(fade * film.load / film.resistance, -limit, limit);
      }
      films_.push_back(film);
      normals.push_back(n);
    }
  // The cells' velocities v_c: each film's (v_b − v_a) · n = V_ab, and the least Σ |v_c|²
  // (no common motion: the fluid carries that). With A the films' rows, v = Aᵀ λ,
  // (A Aᵀ) λ = V; a chain or tree of films gets its speeds exactly, a closed loop of them
  // in the least-squares sense.
  std::vector<std::array<double, 3>> velocity(cells, {0.0, 0.0, 0.0});
  if (!films_.empty()) {
    const int rows = static_cast<int>(films_.size());
    Eigen::MatrixXd constraints = Eigen::MatrixXd::Zero(rows, 3 * cells);
    Eigen::VectorXd speeds(rows);
    for (int r = 0; r < rows; ++r) {
      for (int i = 0; i < 3; ++i) {
        constraints(r, 3 * films_[r].b + i) = normals[r][i];
        constraints(r, 3 * films_[r].a + i) = -normals[r][i];
      }
      speeds[r] = films_[r].opening_speed;
    }
    const Eigen::VectorXd multipliers =
        (constraints * constraints.transpose()).completeOrthogonalDecomposition().solve(speeds);
    const Eigen::VectorXd v = constraints.transpose() * multipliers;
    for (int c = 0; c < cells; ++c)
      for (int i = 0; i < 3; ++i) velocity[c][i] = v[3 * c + i];
  }
  auto host_velocity = Kokkos::create_mirror_view(cell_velocity_);
  for (int c = 0; c < cells; ++c)
    for (int i = 0; i < 3; ++i) host_velocity(c, i) = velocity[c][i] / velocity_scale;
  Kokkos::deep_copy(cell_velocity_, host_velocity);
  // v_n = I u (n) + the films' velocity of n's cell.
  const auto node_cell = population_.node_cell();
  const auto cell_velocity = cell_velocity_;
  Kokkos::parallel_for(
      "rouleau::FilmDrainage::add", Kokkos::RangePolicy<ExecSpace>(0, velocities.extent(0)), KOKKOS_LAMBDA(const int n) {
        for (int i = 0; i < 3; ++i) velocities(n, i) = interpolated(n, i) + cell_velocity(node_cell(n), i);
      });
}

}  // namespace rouleau
