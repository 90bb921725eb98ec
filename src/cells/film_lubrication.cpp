#include "cells/film_lubrication.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace rouleau {

std::vector<std::vector<double>> squeeze_resistances(const FilmPatch& film, double viscosity, double open_gap,
                                                     const std::vector<std::vector<double>>& rates) {
  const int nodes = static_cast<int>(film.points.size());
  const int modes = static_cast<int>(rates.size());
  if (static_cast<int>(film.gap.size()) != nodes)
    throw std::invalid_argument("rouleau::squeeze_resistance: one gap per point is needed");
  for (const auto& rate : rates)
    if (static_cast<int>(rate.size()) != nodes)
      throw std::invalid_argument("rouleau::squeeze_resistance: one closing rate per point is needed");
  for (const double g : film.gap)
    if (!(g > 0.0)) throw std::invalid_argument("rouleau::squeeze_resistance: a gap must be > 0");
  std::vector<std::vector<double>> resistance(modes, std::vector<double>(modes, 0.0));
  // The patch's edge: edges of one triangle only.
  std::map<std::pair<int, int>, int> edge_count;
  for (const auto& t : film.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a < 0 || a >= nodes || b < 0 || b >= nodes)
        throw std::invalid_argument("rouleau::squeeze_resistance: a triangle's index is out of range");
      ++edge_count[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<char> open(nodes, 0);
  for (int n = 0; n < nodes; ++n) open[n] = film.gap[n] >= open_gap;
  for (const auto& [edge, count] : edge_count)
    if (count == 1) open[edge.first] = open[edge.second] = 1;
  // The film's nodes, numbered.
  std::vector<int> unknown(nodes, -1);
  int unknowns = 0;
  for (int n = 0; n < nodes; ++n)
    if (!open[n]) unknown[n] = unknowns++;
  if (unknowns == 0) return resistance;
  // Linear triangles: K_ij = h̄³ (e_i · e_j) / (4 A), e_i the edge opposite node i, h̄³ the
  // mean of the nodal h³; mode m's load 12 μ V_m,i A / 3 per node (lumped).
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> area_weight(nodes, 0.0);
  for (const auto& t : film.triangles) {
    Eigen::Vector3d x[3];
    for (int k = 0; k < 3; ++k) x[k] = Eigen::Vector3d(film.points[t[k]][0], film.points[t[k]][1], film.points[t[k]][2]);
    const Eigen::Vector3d e[3] = {x[2] - x[1], x[0] - x[2], x[1] - x[0]};
    const double area = 0.5 * e[2].cross(-e[1]).norm();
    if (area <= 0.0) continue;
    double mean_cube = 0.0;
    for (int k = 0; k < 3; ++k) mean_cube += std::pow(film.gap[t[k]], 3) / 3.0;
    for (int i = 0; i < 3; ++i) {
      area_weight[t[i]] += area / 3.0;
      if (unknown[t[i]] < 0) continue;
      for (int j = 0; j < 3; ++j)
        if (unknown[t[j]] >= 0)
          entries.emplace_back(unknown[t[i]], unknown[t[j]], mean_cube * e[i].dot(e[j]) / (4.0 * area));
    }
  }
  Eigen::SparseMatrix<double> stiffness(unknowns, unknowns);
  stiffness.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(stiffness);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("rouleau::squeeze_resistance: the film's system is singular");
  // Mode m's pressure p_m, and Z_mn = ∫ p_m V_n dA with the lumped area weights.
  Eigen::MatrixXd load(unknowns, modes);
  for (int n = 0; n < nodes; ++n)
    if (unknown[n] >= 0)
      for (int m = 0; m < modes; ++m) load(unknown[n], m) = 12.0 * viscosity * rates[m][n] * area_weight[n];
  const Eigen::MatrixXd pressure = solver.solve(load);
  for (int n = 0; n < nodes; ++n)
    if (unknown[n] >= 0)
      for (int m = 0; m < modes; ++m)
        for (int k = 0; k < modes; ++k) resistance[m][k] += pressure(unknown[n], m) * rates[k][n] * area_weight[n];
  return resistance;
}

double squeeze_resistance(const FilmPatch& film, double viscosity, double open_gap) {
  const auto resistance =
      squeeze_resistances(film, viscosity, open_gap, {std::vector<double>(film.points.size(), 1.0)});
  return resistance[0][0];
}

}  // namespace rouleau
