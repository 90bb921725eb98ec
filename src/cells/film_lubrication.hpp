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

}  // namespace rouleau
