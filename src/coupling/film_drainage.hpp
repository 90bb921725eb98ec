#pragma once
// The sub-grid film model: plasma films between cells thinner than the fluid mesh resolves.
//
// Where two cells' outer surfaces come closer than about one fluid element, the RKPM
// kernel gives both faces the same smoothed velocity, and the film between them can
// neither drain nor fill: cells pressed together stay at their gap, and cells pulled apart
// stay together (a stack sheared without any interaction turns as one body). The film's
// own physics is lubrication. Two models (coupling.film_model) share what follows.
//
// Rigid films: for each pair of cells (A, B) closer than the open gap h_o,
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
// the fluid.
//
// Deforming films: each film opens as rigid films do, its two cells moved apart as wholes
// along the film's axis, and its faces deform besides, by five smooth modes
// ψ_m = ξ, η, ξ², ξη, η² of the film's tangent coordinates (ξ, η about its centre, in units
// of its rms radius), each less its mean ψ̄_m over the film (weighed by area and w below) so
// that it moves no net volume: the film may open, tilt and dish. The opening mode moves every node of A by
// −½ a and of B by +½ a (a the film's axis, from A to B); face mode m moves side A's film node
// k, and the nodes within the membrane's depth below it, by −½ w_k (ψ_m(x_k) − ψ̄_m) n_k (n_k the
// node's outward normal, w_k = (1 − h_k/h_o)²; side B alike). With Φ the modes' node moves,
// their speeds q solve the backward-Euler balance of the films' squeeze resistance with the
// cells' forces,
//     (Z − Δt Ψᵀ K Φ) q = Ψᵀ f,
// Z the resistance matrix of Reynolds' equation for the films' local rates (1 and the
// w (ψ_m − ψ̄_m): a film's opening rate gathers every opening mode that moves one of its cells; the
// mean of both sides' patches; cells/film_lubrication.hpp), f the forces the fluid felt and
// K = ∂f/∂x the cells' stiffness about x^n, elastic and interaction (the semi-implicit
// coupling's, coupling/cell_stiffness.hpp). Ψ is Φ for the face modes, so for them q
// minimizes ½ Δt qᵀZq + E(x^n + Δt Φq), the films' dissipation over the step plus the cells'
// energy at its end (E to second order, f = −∂E/∂x). For an opening mode Ψ is its move on
// the films' nodes alone, weighed by each film's fade w̄ = (1 − h_min/h_o)²: its load is the
// force the film holds, w̄ T as rigid films read it, since the flow pulls on a locked film
// through the plasma in it, which no energy of the cells' sees (a cell moved as a whole keeps
// its elastic energy). The faces can flatten against each other where an adhesion pulls, and
// the cells part where the flow pulls harder. The largest node rate is held to a quarter of
// the node's gap per step (all speeds scaled alike).
//
// Host-side (a few thousand surface nodes per pair), on the cells' current positions.
#include <array>
#include <optional>
#include <vector>

#include "cells/cell_gaps.hpp"
#include "cells/cell_population.hpp"
#include "cells/film_lubrication.hpp"
#include "config/case_config.hpp"

namespace rouleau {

class CellStiffness;

class FilmDrainage {
 public:
  struct Film {
    int a = 0, b = 0;
    double smallest_gap = 0.0;   // [μm]
    double load = 0.0;           // T [pN], > 0 pulling open (deforming: the opening mode's Ψᵀ f, w̄ T)
    double resistance = 0.0;     // ζ [pN·s/μm] (deforming: the film's Z for the opening rate 1)
    double opening_speed = 0.0;  // V [μm/s], after fading and the step's limit (deforming: the
                                 // mean local rate over A's film nodes)
  };

  // `open_gap` [μm] > 0, `viscosity` [Pa·s].
  FilmDrainage(const CellPopulation& population, double open_gap, double viscosity,
               FilmModel model = FilmModel::rigid);

  // velocities = interpolated + the films' velocities / velocity_scale, for the forces the
  // fluid felt this step at the population's current positions and the step `dt` [s];
  // `interpolated` and `velocities` scaled by velocity_scale [μm/s] (the fluid's).
  // `stiffness` (deforming films; linearized about the current positions this step) or
  // null: deforming films then balance Z q = Φᵀ f alone (explicit in the cells' forces).
  void add_opening_velocities(CellPopulation::ConstNodeVectors felt_forces,
                              CellPopulation::ConstNodeVectors interpolated, CellPopulation::NodeVectors velocities,
                              double dt, double velocity_scale, const CellStiffness* stiffness = nullptr);

  // The films of the last step (pairs closer than the open gap).
  const std::vector<Film>& films() const { return films_; }

 private:
  // A film's tangent frame and its local rates (deforming films).
  struct FilmFrame {
    static constexpr int modes = 6;
    using Modes = std::array<double, modes>;
    std::array<double, 3> centre{0.0, 0.0, 0.0}, e1{0.0, 0.0, 0.0}, e2{0.0, 0.0, 0.0};
    double radius = 1.0;  // rms radius [μm]
    Modes mean{};         // the face modes' ψ̄_m over the film (area and fade weighed)
    // ψ_m at a point (0 for the opening).
    Modes shapes(const std::array<double, 3>& point) const;
    // The local rates (the opening's 1, the face modes' w (ψ_m − ψ̄_m)) at a point of gap h.
    Modes local_rates(const std::array<double, 3>& point, double h, double open_gap) const;
  };
  std::optional<FilmFrame> film_frame(const int (&side_cell)[2], const std::vector<double>* const (&side_distance)[2],
                                      const std::vector<std::array<double, 3>>& normal) const;
  std::vector<std::array<double, 3>> outward_normals() const;
  // Cell c's film patch toward another cell (distance: c's nodes' distances to it).
  FilmPatch film_patch(int c, const std::vector<double>& distance, std::vector<int>* node_of) const;
  // Deforming films: the triangles' orientation and the node each node follows.
  void find_followed_nodes();
  // Deforming films: velocities = interpolated + Σ_j q_j Φ_j, for films_ and their
  // nodes' distances (per film: A's to B, B's to A).
  void deform_films(const std::vector<std::vector<double>>& distances, CellPopulation::ConstNodeVectors interpolated,
                    CellPopulation::NodeVectors velocities, double dt, double velocity_scale,
                    const CellStiffness* stiffness);
  const CellPopulation& population_;
  double open_gap_, viscosity_;
  FilmModel model_;
  CellGaps gaps_;
  std::vector<std::vector<int>> cell_triangles_;  // per cell, its outer-surface triangles
  std::vector<std::array<int, 3>> triangles_;     // the outer-surface triangles' nodes
  std::vector<Film> films_;
  Kokkos::View<double* [3]> cell_velocity_;       // per cell, the films' velocity
  std::vector<double> area_weight_;               // per node, its outer-surface area (reference) [μm²]
  std::vector<double> outward_;                   // per cell, +1 when its triangles face outward, else −1
  std::vector<int> surface_node_;                 // per node, the outer-surface node it follows (−1: none)
  Kokkos::View<double* [3]> node_velocity_;       // per node, the films' velocity
  // Deforming films: a mode's node moves Φ_j and the force change K Φ_j (scratch).
  Kokkos::View<double* [3]> mode_moves_, mode_force_change_;
  std::vector<std::array<double, 3>> positions_, forces_;  // this step's, on the host
};

}  // namespace rouleau
