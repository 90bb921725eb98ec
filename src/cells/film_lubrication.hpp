#pragma once
// The squeeze resistance of a thin film of plasma between two cell surfaces, below the
// fluid mesh's resolution: Reynolds' lubrication equation (Reynolds 1886) on one side's
// surface patch. Where two surfaces are h apart and approach each other at V, the film's
// pressure p solves
//     −∇_s · (h³ ∇_s p) = 12 μ V          on the film,
//     p = 0                               where it opens (h ≥ the open gap) and at the patch's edge,
// and the film resists with F = ∫ p dA. F is linear in V; squeeze_resistance returns
// F / V [pN·s/μm], so a film that holds a load T opens at V = −T / (F / V) when pulled
// apart. For a sphere of radius R at gap h from a plane, F / V → 6 π μ R² / h (the Reynolds
// limit of Brenner 1961); for two coaxial discs of radius a, 3 π μ a⁴ / (2 h³) (Stefan 1874).
// Linear triangles; host-only.
#include <array>
#include <vector>

namespace rouleau {

struct FilmPatch {
  std::vector<std::array<double, 3>> points;  // the nodes [μm]
  std::vector<std::array<int, 3>> triangles;  // indices into points
  std::vector<double> gap;                    // per node: the distance to the other surface [μm]
};

// F / V for `film` and plasma of viscosity `viscosity` [Pa·s = pN·s/μm²]; the film is open
// (p = 0) at nodes whose gap is at least `open_gap` [μm] and at the patch's edge (nodes on
// an edge of one triangle only). Throws std::invalid_argument for a gap ≤ 0 or an index
// out of range; 0 when no node is inside the film.
double squeeze_resistance(const FilmPatch& film, double viscosity, double open_gap);

// The film closing at a rate that varies over it: for closing rates V_m (one value per
// point, [μm/s], m = 1..M), the resistance matrix Z_mn = ∫ p_m V_n dA [pN·s/μm], p_m the
// pressure of Reynolds' equation with V_m on its right-hand side (same boundary conditions).
// Z is symmetric positive semi-definite; squeeze_resistance is Z for the one rate V = 1.
// For loads F_i on the points (> 0 closing) the film closes, within the span of the V_m,
// at Σ_m q_m V_m with Z q = Q, Q_m = Σ_i F_i V_m,i: the rates that dissipate what the loads
// do work, as Stokes' equations do (Galerkin on the modes).
std::vector<std::vector<double>> squeeze_resistances(const FilmPatch& film, double viscosity, double open_gap,
                                                     const std::vector<std::vector<double>>& rates);

}  // namespace rouleau
