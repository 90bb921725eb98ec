#include "coupling/film_drainage.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>

#include "cells/film_lubrication.hpp"
#include "coupling/cell_stiffness.hpp"
#include "util/profiling_region.hpp"

namespace rouleau {

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;
// A node's gap is taken as at least this [μm] in Reynolds' equation: surfaces that touch
// or overlap leave a film of molecular size, not none.
constexpr double least_gap = 1e-3;
// How deep below the outer surface a node follows its film [μm]: the shell's 0.36 μm and more.
constexpr double membrane_depth = 0.6;
// The fade w = (1 − h/h_o)² by which the model hands a film of gap h to the fluid as it
// nears the open gap h_o.
double fade(double h, double open_gap) { return (1.0 - h / open_gap) * (1.0 - h / open_gap); }
// velocities = interpolated + node_velocity (a free function: CUDA's device lambdas may not
// sit in a private member).
void add_node_velocities(CellPopulation::ConstNodeVectors interpolated, Kokkos::View<const double* [3]> node_velocity,
                         CellPopulation::NodeVectors velocities) {
  Kokkos::parallel_for(
      "rouleau::FilmDrainage::add_node_velocities", Kokkos::RangePolicy<ExecSpace>(0, velocities.extent(0)),
      KOKKOS_LAMBDA(const int n) {
        for (int i = 0; i < 3; ++i) velocities(n, i) = interpolated(n, i) + node_velocity(n, i);
      });
}
}  // namespace

FilmDrainage::FilmDrainage(const CellPopulation& population, double open_gap, double viscosity, FilmModel model)
    : population_(population),
      open_gap_(open_gap),
      viscosity_(viscosity),
      model_(model),
      gaps_(population, open_gap),
      cell_velocity_("rouleau::FilmDrainage::cell_velocity", population.num_cells()) {
  if (!(open_gap > 0.0)) throw std::invalid_argument("rouleau::FilmDrainage: the open gap must be > 0");
  auto triangle_cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.triangle_cell());
  const auto triangles = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_triangles());
  for (std::size_t t = 0; t < triangles.extent(0); ++t)
    triangles_.push_back({triangles(t, 0), triangles(t, 1), triangles(t, 2)});
  cell_triangles_.assign(population.num_cells(), {});
  for (std::size_t t = 0; t < triangle_cell.extent(0); ++t) cell_triangles_[triangle_cell(t)].push_back(int(t));
  if (model_ == FilmModel::deforming) find_followed_nodes();
}

void FilmDrainage::find_followed_nodes() {
  const CellPopulation& population = population_;
  // Which way the triangles face: outward when the volume they enclose is positive.
  const auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.reference_positions());
  const auto w = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), population.surface_area_weights());
  area_weight_.assign(w.data(), w.data() + w.extent(0));
  outward_.assign(population.num_cells(), 1.0);
  for (int c = 0; c < population.num_cells(); ++c) {
    double volume = 0.0;
    for (const int t : cell_triangles_[c]) {
      const auto& k = triangles_[t];
      const double a[3] = {x0(k[0], 0), x0(k[0], 1), x0(k[0], 2)};
      const double b[3] = {x0(k[1], 0), x0(k[1], 1), x0(k[1], 2)};
      const double d[3] = {x0(k[2], 0), x0(k[2], 1), x0(k[2], 2)};
      volume += a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                a[2] * (b[0] * d[1] - b[1] * d[0]);
    }
    outward_[c] = volume >= 0.0 ? 1.0 : -1.0;
  }
  // Each node follows the nearest outer-surface node of its cell (in the reference
  // configuration) within the membrane's depth, so a film moves the membrane's whole
  // thickness, not its outer face alone.
  const auto& first = population.cell_first_node();
  const auto& count = population.cell_node_count();
  surface_node_.assign(population.num_nodes(), -1);
  for (int c = 0; c < population.num_cells(); ++c) {
    std::vector<int> surface;
    for (int n = first[c]; n < first[c] + count[c]; ++n)
      if (w(n) > 0.0) surface.push_back(n);
    for (int n = first[c]; n < first[c] + count[c]; ++n) {
      double nearest = membrane_depth * membrane_depth;
      for (const int s : surface) {
        double d2 = 0.0;
        for (int k = 0; k < 3; ++k) d2 += (x0(n, k) - x0(s, k)) * (x0(n, k) - x0(s, k));
        if (d2 <= nearest) {
          nearest = d2;
          surface_node_[n] = s;
        }
      }
    }
  }
  node_velocity_ = Kokkos::View<double* [3]>("rouleau::FilmDrainage::node_velocity", population.num_nodes());
  mode_moves_ = Kokkos::View<double* [3]>("rouleau::FilmDrainage::mode_moves", population.num_nodes());
  mode_force_change_ = Kokkos::View<double* [3]>("rouleau::FilmDrainage::mode_force_change", population.num_nodes());
}

// Cell c's film patch: its outer-surface triangles whose nodes are all within twice the
// open gap of the other cell (distance[k] for c's node first[c] + k), at positions_;
// node_of (when given) receives each patch point's node.
FilmPatch FilmDrainage::film_patch(int c, const std::vector<double>& distance, std::vector<int>* node_of) const {
  const int first = population_.cell_first_node()[c], count = population_.cell_node_count()[c];
  FilmPatch film;
  std::vector<int> local(count, -1);
  for (const int t : cell_triangles_[c]) {
    bool near = true;
    for (int k = 0; k < 3; ++k) near = near && distance[triangles_[t][k] - first] < 2.0 * open_gap_;
    if (!near) continue;
    std::array<int, 3> corners{};
    for (int k = 0; k < 3; ++k) {
      const int node = triangles_[t][k], j = node - first;
      if (local[j] < 0) {
        local[j] = static_cast<int>(film.points.size());
        film.points.push_back(positions_[node]);
        film.gap.push_back(std::max(distance[j], least_gap));
        if (node_of) node_of->push_back(node);
      }
      corners[k] = local[j];
    }
    film.triangles.push_back(corners);
  }
  return film;
}

void FilmDrainage::add_opening_velocities(CellPopulation::ConstNodeVectors felt_forces,
                                          CellPopulation::ConstNodeVectors interpolated,
                                          CellPopulation::NodeVectors velocities, double dt,
                                          double velocity_scale, const CellStiffness* stiffness) {
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
  positions_.resize(x.extent(0));
  for (std::size_t n = 0; n < x.extent(0); ++n) positions_[n] = {x(n, 0), x(n, 1), x(n, 2)};
  forces_.resize(f.extent(0));
  for (std::size_t n = 0; n < f.extent(0); ++n) forces_[n] = {f(n, 0), f(n, 1), f(n, 2)};
  // T_c = −Σ f_i · n over c's nodes inside the film, n pointing to the other cell.
  const auto load = [&](int c, const std::vector<double>& distance, const std::array<double, 3>& n) {
    double sum = 0.0;
    for (int k = 0; k < count[c]; ++k)
      if (distance[k] < open_gap_) {
        const int node = first[c] + k;
        sum -= forces_[node][0] * n[0] + forces_[node][1] * n[1] + forces_[node][2] * n[2];
      }
    return sum;
  };

  const bool deforming = model_ == FilmModel::deforming;
  std::vector<std::vector<double>> film_distances;  // deforming: per film, from_a then from_b
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
      if (deforming) {
        films_.push_back(film);
        film_distances.push_back(from_a);
        film_distances.push_back(from_b);
        continue;
      }
      const std::array<double, 3> reversed{-n[0], -n[1], -n[2]};
      film.load = 0.5 * (load(a, from_a, n) + load(b, from_b, reversed));
      const double resistance_a = squeeze_resistance(film_patch(a, from_a, nullptr), viscosity_, open_gap_);
      const double resistance_b = squeeze_resistance(film_patch(b, from_b, nullptr), viscosity_, open_gap_);
      film.resistance = resistance_a > 0.0 && resistance_b > 0.0 ? 0.5 * (resistance_a + resistance_b)
                                                                 : std::max(resistance_a, resistance_b);
      if (film.resistance > 0.0) {
        const double limit = 0.25 * smallest_gap / dt;
        film.opening_speed = std::clamp(fade(smallest_gap, open_gap_) * film.load / film.resistance, -limit, limit);
      }
      films_.push_back(film);
      normals.push_back(n);
    }
  if (deforming) {
    deform_films(film_distances, interpolated, velocities, dt, velocity_scale, stiffness);
    return;
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

// Each outer-surface node's unit outward normal at positions_: the mean of its triangles'
// area vectors.
std::vector<std::array<double, 3>> FilmDrainage::outward_normals() const {
  std::vector<std::array<double, 3>> normal(positions_.size(), {0.0, 0.0, 0.0});
  for (int c = 0; c < population_.num_cells(); ++c)
    for (const int t : cell_triangles_[c]) {
      const auto& k = triangles_[t];
      double e1[3], e2[3];
      for (int i = 0; i < 3; ++i) {
        e1[i] = positions_[k[1]][i] - positions_[k[0]][i];
        e2[i] = positions_[k[2]][i] - positions_[k[0]][i];
      }
      const double area_vector[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                     e1[0] * e2[1] - e1[1] * e2[0]};
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) normal[k[j]][i] += outward_[c] * area_vector[i];
    }
  for (auto& n : normal) {
    const double length = std::hypot(n[0], n[1], n[2]);
    if (length > 0.0)
      for (double& component : n) component /= length;
  }
  return normal;
}

// A film's frame: the area-weighted centre of both sides' film nodes (gap below the open
// gap), the unit axis from side A to side B (their outward normals' weighted difference),
// tangent axes e1, e2 and the rms radius about the centre; none for an empty film.
std::optional<FilmDrainage::FilmFrame> FilmDrainage::film_frame(
    const int (&side_cell)[2], const std::vector<double>* const (&side_distance)[2],
    const std::vector<std::array<double, 3>>& normal) const {
  const auto& first = population_.cell_first_node();
  const auto& count = population_.cell_node_count();
  FilmFrame frame;
  double area = 0.0;
  std::array<double, 3> axis{0.0, 0.0, 0.0};
  for (int side = 0; side < 2; ++side) {
    const int c = side_cell[side];
    for (int k = 0; k < count[c]; ++k)
      if ((*side_distance[side])[k] < open_gap_) {
        const int node = first[c] + k;
        area += area_weight_[node];
        for (int i = 0; i < 3; ++i) {
          frame.centre[i] += area_weight_[node] * positions_[node][i];
          axis[i] += (side == 0 ? 1.0 : -1.0) * area_weight_[node] * normal[node][i];
        }
      }
  }
  const double axis_length = std::hypot(axis[0], axis[1], axis[2]);
  if (!(area > 0.0) || !(axis_length > 0.0)) return std::nullopt;
  for (int i = 0; i < 3; ++i) {
    frame.centre[i] /= area;
    axis[i] /= axis_length;
  }
  // e1: the coordinate axis least along the film's axis, made normal to it; e2 = axis × e1.
  int least = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(axis[i]) < std::abs(axis[least])) least = i;
  frame.e1[least] = 1.0;
  const double along = frame.e1[0] * axis[0] + frame.e1[1] * axis[1] + frame.e1[2] * axis[2];
  for (int i = 0; i < 3; ++i) frame.e1[i] -= along * axis[i];
  const double e1_length = std::hypot(frame.e1[0], frame.e1[1], frame.e1[2]);
  for (double& component : frame.e1) component /= e1_length;
  frame.e2 = {axis[1] * frame.e1[2] - axis[2] * frame.e1[1], axis[2] * frame.e1[0] - axis[0] * frame.e1[2],
              axis[0] * frame.e1[1] - axis[1] * frame.e1[0]};
  double radius2 = 0.0;
  for (int side = 0; side < 2; ++side) {
    const int c = side_cell[side];
    for (int k = 0; k < count[c]; ++k)
      if ((*side_distance[side])[k] < open_gap_) {
        const int node = first[c] + k;
        for (int i = 0; i < 3; ++i)
          radius2 += area_weight_[node] * (positions_[node][i] - frame.centre[i]) *
                     (positions_[node][i] - frame.centre[i]);
      }
  }
  frame.radius = std::sqrt(std::max(radius2 / area, 1e-12));
  // The face modes' means over the film, weighed by area and fade, taken off them: they
  // then move no net volume of plasma, which the opening mode alone does.
  double weight = 0.0;
  FilmFrame::Modes sum{};
  for (int side = 0; side < 2; ++side) {
    const int c = side_cell[side];
    for (int k = 0; k < count[c]; ++k) {
      const double h = (*side_distance[side])[k];
      if (!(h < open_gap_)) continue;
      const int node = first[c] + k;
      const double w = area_weight_[node] * fade(h, open_gap_);
      const FilmFrame::Modes psi = frame.shapes(positions_[node]);
      weight += w;
      for (int m = 1; m < FilmFrame::modes; ++m) sum[m] += w * psi[m];
    }
  }
  if (weight > 0.0)
    for (int m = 1; m < FilmFrame::modes; ++m) frame.mean[m] = sum[m] / weight;
  return frame;
}

// ψ_m at `point`: 0 for the opening, then ξ, η, ξ², ξη, η².
FilmDrainage::FilmFrame::Modes FilmDrainage::FilmFrame::shapes(const std::array<double, 3>& point) const {
  double xi = 0.0, eta = 0.0;
  for (int i = 0; i < 3; ++i) {
    xi += (point[i] - centre[i]) * e1[i] / radius;
    eta += (point[i] - centre[i]) * e2[i] / radius;
  }
  return {0.0, xi, eta, xi * xi, xi * eta, eta * eta};
}

// A film's local rates at `point`, gap h: the opening's 1 and the face modes'
// w (ψ_m − ψ̄_m), w = (1 − h/h_o)² (all zero beyond h_o).
FilmDrainage::FilmFrame::Modes FilmDrainage::FilmFrame::local_rates(const std::array<double, 3>& point, double h,
                                                                    double open_gap) const {
  Modes value{};
  if (!(h < open_gap)) return value;
  const double w = fade(h, open_gap);
  const Modes psi = shapes(point);
  value[0] = 1.0;
  for (int m = 1; m < modes; ++m) value[m] = w * (psi[m] - mean[m]);
  return value;
}

// The deforming films (coupling/film_drainage.hpp): per film its opening mode (the two cells
// moved apart as wholes along the film's axis) and five face modes; the films' resistance
// Z, the loads Ψᵀ f, the stiffness Ψᵀ K Φ by one action of K per mode, then q and the
// velocities.
void FilmDrainage::deform_films(const std::vector<std::vector<double>>& distances,
                                CellPopulation::ConstNodeVectors interpolated, CellPopulation::NodeVectors velocities,
                                double dt, double velocity_scale, const CellStiffness* stiffness) {
  // Per film: mode 0 the opening (rigid), modes 1..5 the faces' ξ, η, ξ², ξη, η².
  constexpr int modes_per_film = FilmFrame::modes;
  const int nodes = population_.num_nodes();
  const int films = static_cast<int>(films_.size());
  const int modes = modes_per_film * films;
  const auto& first = population_.cell_first_node();
  const auto& count = population_.cell_node_count();
  const std::vector<std::array<double, 3>> normal = outward_normals();
  // Φ_j per node (3 per node); per film its axis (from A to B), its fade w̄ and its local
  // resistance Z_f over the rates (1, w ψ_1, ..., w ψ_5); per node the fade of the film it
  // lies in (0 outside every film), which weighs the opening modes' loads; for the step's
  // limit the film nodes' local rates and gaps.
  std::vector<std::vector<double>> shapes(modes, std::vector<double>(3 * nodes, 0.0));
  std::vector<std::array<double, 3>> axis(films, {0.0, 0.0, 0.0});
  std::vector<double> film_fade(films, 0.0), load_weight(nodes, 0.0);
  std::vector<Eigen::MatrixXd> local_resistance(films, Eigen::MatrixXd::Zero(modes_per_film, modes_per_film));
  struct RatePoint {
    int film;
    double gap;
    FilmFrame::Modes rate;  // 1, w ψ_1, ..., w ψ_5
  };
  std::vector<RatePoint> rate_points;
  for (int film = 0; film < films; ++film) {
    const int side_cell[2] = {films_[film].a, films_[film].b};
    const std::vector<double>* side_distance[2] = {&distances[2 * film], &distances[2 * film + 1]};
    const std::optional<FilmFrame> frame = film_frame(side_cell, side_distance, normal);
    if (!frame) continue;
    const auto& e1 = frame->e1;
    const auto& e2 = frame->e2;
    axis[film] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    film_fade[film] = fade(films_[film].smallest_gap, open_gap_);
    for (int side = 0; side < 2; ++side) {
      const int c = side_cell[side];
      const std::vector<double>& distance = *side_distance[side];
      // The opening mode: every node of A by −½ axis, of B by +½ axis.
      const double sign = side == 0 ? -0.5 : 0.5;
      for (int n = first[c]; n < first[c] + count[c]; ++n)
        for (int i = 0; i < 3; ++i) shapes[modes_per_film * film][3 * n + i] = sign * axis[film][i];
      // Z from this side's patch, half of the film's.
      std::vector<int> node_of;
      const FilmPatch patch = film_patch(c, distance, &node_of);
      std::vector<std::vector<double>> rates(modes_per_film, std::vector<double>(node_of.size(), 0.0));
      for (std::size_t p = 0; p < node_of.size(); ++p) {
        const auto value = frame->local_rates(patch.points[p], patch.gap[p], open_gap_);
        for (int m = 0; m < modes_per_film; ++m) rates[m][p] = value[m];
      }
      const auto side_resistance = squeeze_resistances(patch, viscosity_, open_gap_, rates);
      for (int m = 0; m < modes_per_film; ++m)
        for (int k = 0; k < modes_per_film; ++k) local_resistance[film](m, k) += 0.5 * side_resistance[m][k];
      // The face modes: the film node and the nodes that follow it.
      std::vector<FilmFrame::Modes> node_rate(count[c]);
      std::vector<char> in_film(count[c], 0);
      for (int k = 0; k < count[c]; ++k) {
        const int node = first[c] + k;
        const double h = std::max(distance[k], least_gap);
        if (!(h < open_gap_)) continue;
        in_film[k] = 1;
        load_weight[node] = std::max(load_weight[node], film_fade[film]);
        node_rate[k] = frame->local_rates(positions_[node], h, open_gap_);
        if (side == 0) rate_points.push_back({film, h, node_rate[k]});
      }
      for (int k = 0; k < count[c]; ++k) {
        const int node = first[c] + k, followed = surface_node_[node];
        if (followed < 0 || !in_film[followed - first[c]]) continue;
        for (int m = 1; m < modes_per_film; ++m)
          for (int i = 0; i < 3; ++i)
            shapes[modes_per_film * film + m][3 * node + i] =
                -0.5 * node_rate[followed - first[c]][m] * normal[followed][i];
      }
    }
  }
  // The local rates of film f from the speeds q: r_f = P_f q, its opening rate from every
  // opening mode that moves one of its cells, r_f0 = Σ_g ((t_g(B_f) − t_g(A_f)) · axis_f) q_g0
  // (t_g(c) = ∓½ axis_g for g's cells), and its own face modes.
  std::vector<Eigen::MatrixXd> to_local(films, Eigen::MatrixXd::Zero(modes_per_film, modes));
  const auto moves_cell = [&](int g, int c) {
    const double sign = c == films_[g].a ? -0.5 : c == films_[g].b ? 0.5 : 0.0;
    return std::array<double, 3>{sign * axis[g][0], sign * axis[g][1], sign * axis[g][2]};
  };
  for (int film = 0; film < films; ++film) {
    for (int g = 0; g < films; ++g) {
      const auto on_b = moves_cell(g, films_[film].b), on_a = moves_cell(g, films_[film].a);
      double rate = 0.0;
      for (int i = 0; i < 3; ++i) rate += (on_b[i] - on_a[i]) * axis[film][i];
      to_local[film](0, modes_per_film * g) = rate;
    }
    for (int m = 1; m < modes_per_film; ++m) to_local[film](m, modes_per_film * film + m) = 1.0;
  }
  // Z = Σ_f P_fᵀ Z_f P_f.
  Eigen::MatrixXd resistance = Eigen::MatrixXd::Zero(modes, modes);
  for (int film = 0; film < films; ++film)
    resistance += to_local[film].transpose() * local_resistance[film] * to_local[film];
  // Ψ_j: Φ_j for a face mode; for an opening mode Φ_j on the films' nodes alone, each
  // weighed by its film's fade, so its load is the force the films hold (w̄ T for a lone pair).
  const auto load_shape = [&](int j, int n, int i) {
    return j % modes_per_film == 0 ? load_weight[n] * shapes[j][3 * n + i] : shapes[j][3 * n + i];
  };
  // Q = Ψᵀ f, and the stiffness Ψᵀ K Φ.
  Eigen::VectorXd loads = Eigen::VectorXd::Zero(modes);
  for (int j = 0; j < modes; ++j)
    for (int n = 0; n < nodes; ++n)
      for (int i = 0; i < 3; ++i) loads[j] += load_shape(j, n, i) * forces_[n][i];
  Eigen::MatrixXd system = resistance;
  if (stiffness && modes > 0) {
    const CellPopulation::NodeVectors moves = mode_moves_, change = mode_force_change_;
    auto host_moves = Kokkos::create_mirror_view(moves);
    for (int j = 0; j < modes; ++j) {
      for (int n = 0; n < nodes; ++n)
        for (int i = 0; i < 3; ++i) host_moves(n, i) = shapes[j][3 * n + i];
      Kokkos::deep_copy(moves, host_moves);
      stiffness->moves_force_change(moves, change);
      const auto host_change = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), change);
      for (int k = 0; k < modes; ++k) {
        double sum = 0.0;
        for (int n = 0; n < nodes; ++n)
          for (int i = 0; i < 3; ++i) sum += load_shape(k, n, i) * host_change(n, i);
        system(k, j) -= dt * sum;
      }
    }
  }
  // Solve in the span of Z's well-resolved combinations (eigenvalues above 1e-10 of the
  // largest), which the stiffness then couples.
  Eigen::VectorXd speeds = Eigen::VectorXd::Zero(modes);
  if (modes > 0) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(resistance);
    const double largest = eigen.eigenvalues().maxCoeff();
    std::vector<int> kept;
    for (int m = 0; m < modes; ++m)
      if (largest > 0.0 && eigen.eigenvalues()[m] > 1e-10 * largest) kept.push_back(m);
    if (!kept.empty()) {
      Eigen::MatrixXd u(modes, kept.size());
      for (std::size_t b = 0; b < kept.size(); ++b) u.col(b) = eigen.eigenvectors().col(kept[b]);
      const Eigen::MatrixXd reduced = u.transpose() * system * u;
      speeds = u * reduced.fullPivLu().solve(u.transpose() * loads);
    }
  }
  // The step's limit: |V_k| Δt ≤ h_k / 4 at every film node.
  std::vector<Eigen::VectorXd> local_speeds(films);
  for (int film = 0; film < films; ++film) local_speeds[film] = to_local[film] * speeds;
  double excess = 1.0;
  std::vector<double> mean_rate(films, 0.0), rate_count(films, 0.0);
  for (const auto& point : rate_points) {
    double rate = 0.0;
    for (int m = 0; m < modes_per_film; ++m) rate += local_speeds[point.film][m] * point.rate[m];
    excess = std::max(excess, std::abs(rate) * dt / (0.25 * point.gap));
    mean_rate[point.film] += rate;
    rate_count[point.film] += 1.0;
  }
  speeds /= excess;
  for (int film = 0; film < films; ++film) {
    films_[film].load = loads[modes_per_film * film];
    films_[film].resistance = local_resistance[film](0, 0);
    films_[film].opening_speed = rate_count[film] > 0.0 ? mean_rate[film] / rate_count[film] / excess : 0.0;
  }
  // v_n = I u (n) + Σ_j q_j Φ_j(n).
  auto host_node_velocity = Kokkos::create_mirror_view(node_velocity_);
  for (int n = 0; n < nodes; ++n)
    for (int i = 0; i < 3; ++i) {
      double sum = 0.0;
      for (int j = 0; j < modes; ++j) sum += speeds[j] * shapes[j][3 * n + i];
      host_node_velocity(n, i) = sum / velocity_scale;
    }
  Kokkos::deep_copy(node_velocity_, host_node_velocity);
  add_node_velocities(interpolated, node_velocity_, velocities);
}

}  // namespace rouleau
