#pragma once
// The Morse interaction between cell surfaces (paper eqs. 3, 4, 11), the pair physics
// apart from the pair loop.
//
//   φ(r) = De [e^{2β(r0−r)} − 2 e^{β(r0−r)}]             (3)  [pN·μm/μm⁴ = pN/μm³]
//   f(r) = −φ'(r) = 2 De β [e^{2β(r0−r)} − e^{β(r0−r)}]  (4)  [pN/μm⁴], > 0 repulsive
// φ is an energy per area per area: surface node i (area weight w_i on the reference
// surface) and node j of another cell within the cut-off interact with energy
// w_i w_j φ(r_ij) [pN·μm] and force ±w_i w_j f(r_ij) r̂ [pN] — the nodal quadrature of
// the double surface integral of eq. (11), so the discrete force is exactly minus the
// gradient of the discrete energy. Identities: φ(r0) = −De, f(r0) = 0, and the strongest
// attraction, −f = βDe/2, at r = r0 + ln 2/β.
#include <Kokkos_Core.hpp>
#include <cmath>

namespace rouleau {

struct MorsePotential {
  double well_depth = 0.0;          // De [pN/μm³]
  double beta = 1.0;                // β [1/μm]
  double zero_force_length = 0.25;  // r0 [μm]
  double cutoff = 3.0;              // r_c [μm]: no interaction at r ≥ r_c

  KOKKOS_INLINE_FUNCTION double energy(const double r) const {
    const double e = exp(beta * (zero_force_length - r));
    return well_depth * (e * e - 2.0 * e);
  }
  // f(r) = −dφ/dr
  KOKKOS_INLINE_FUNCTION double force(const double r) const {
    const double e = exp(beta * (zero_force_length - r));
    return 2.0 * well_depth * beta * (e * e - e);
  }
  // f(r), with φ(r) in `energy`, from one exponential.
  KOKKOS_INLINE_FUNCTION double force_and_energy(const double r, double& energy) const {
    const double e = exp(beta * (zero_force_length - r));
    energy = well_depth * (e * e - 2.0 * e);
    return 2.0 * well_depth * beta * (e * e - e);
  }
};

}  // namespace rouleau
