#pragma once
// The sub-grid film model: plasma films between cells thinner than the fluid mesh resolves.
//
// Where two cells' outer surfaces come closer than about one fluid element, the RKPM
// kernel gives both faces the same smoothed velocity, and the film between them can
// neither drain nor fill: cells pressed together stay at their gap, and cells pulled apart
// stay together (a stack sheared without any interaction turns as one body). The film's
// own physics is lubrication: for each pair of cells (A, B) closer than the open gap h_o,
//   - the load it holds: T = ½ (T_A + T_B), T_A = −Σ_{i ∈ A, h_i < h_o} f_i · n, with f_i the
//     force node i put into the fluid (what the fluid felt this step), n the unit vector
//     from A's centroid to B's, h_i the node's distance to B's surface (T_B likewise, n
//     reversed); T > 0 pulls the film open;
//   - its squeeze resistance ζ from Reynolds' equation on each side's film patch
//     (cells/film_lubrication.hpp), ζ = ½ (ζ_A + ζ_B);
//   - its opening speed V = w T / ζ, w = (1 − h_min / h_o)² fading the model out as the
//     smallest gap h_min reaches the open gap, where the fluid takes over; |V| Δt is held
//     to at most a quarter of h_min, so a closing film cannot cross in one step.
// Each cell then moves, on top of the velocity interpolated from the fluid, with a velocity
// of its own, as a whole (so its shape and volume do not change): the smallest such
// velocities, in the least-squares sense, for which each film's relative normal speed
// (v_B − v_A) · n is its V; a lone pair moves by −V/2 n and +V/2 n. The model adds the
// relative normal motion the fluid cannot carry; tangential sliding and rolling stay with
// the fluid. Host-side (a few thousand surface nodes per
// pair), on the cells' current positions.
#include <array>
#include <vector>

#include "cells/cell_gaps.hpp"
#include "cells/cell_population.hpp"

namespace rouleau {

class FilmDrainage {
 public:
  struct Film {
    int a = 0, b = 0;
    double smallest_gap = 0.0;   // [μm]
    double load = 0.0;           // T [pN], > 0 pulling open
    double resistance = 0.0;     // ζ [pN·s/μm]
    double opening_speed = 0.0;  // V [μm/s], after fading and the step's limit
  };

  // `open_gap` [μm] > 0, `viscosity` [Pa·s].
  FilmDrainage(const CellPopulation& population, double open_gap, double viscosity);

  // velocities = interpolated + each cell's films' opening velocities / velocity_scale, for
  // the forces the fluid felt this step at the population's current positions and the step
  // `dt` [s]; `interpolated` and `velocities` scaled by velocity_scale [μm/s] (the fluid's).
  void add_opening_velocities(CellPopulation::ConstNodeVectors felt_forces,
                              CellPopulation::ConstNodeVectors interpolated, CellPopulation::NodeVectors velocities,
                              double dt, double velocity_scale);

  // The films of the last step (pairs closer than the open gap).
  const std::vector<Film>& films() const { return films_; }

 private:
  const CellPopulation& population_;
  double open_gap_, viscosity_;
  CellGaps gaps_;
  std::vector<std::vector<int>> cell_triangles_;  // per cell, its outer-surface triangles
  std::vector<std::array<int, 3>> triangles_;     // the outer-surface triangles' nodes
  std::vector<Film> films_;
  Kokkos::View<double* [3]> cell_velocity_;       // per cell, the films' velocity
};

}  // namespace rouleau
