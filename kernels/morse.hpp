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
//
// Truncated at r_c, the law is shifted so that both force and energy vanish there (the
// "shifted-force" form; LAMMPS' morse/smooth/linear):
//   f_s(r) = f(r) − f(r_c),   φ_s(r) = φ(r) − φ(r_c) + (r − r_c) f(r_c),   f_s = −φ_s'.
// The shift is tiny (|f(r_c)| = 2βDe e^{−β(r_c−r0)}(1 − e^{−β(r_c−r0)}) ≈ 1.3e-4 De for
// β = 4/μm, r_c = 3 μm, against the peak attraction 2 De), but without it the force jumps
// at r_c, and a pair that crosses r_c within the semi-implicit coupling's difference step
// shows a spurious stiffness (coupling/cell_stiffness.hpp). energy()/force() are the
// shifted law; unshifted_energy()/unshifted_force() are eqs. (3) and (4) as printed.
#include <Kokkos_Core.hpp>
#include <cmath>

namespace rouleau {

struct MorsePotential {
  double well_depth = 0.0;          // De [pN/μm³]
  double beta = 1.0;                // β [1/μm]
  double zero_force_length = 0.25;  // r0 [μm]
  double cutoff = 3.0;              // r_c [μm]: no interaction at r ≥ r_c
  double cutoff_force = 0.0;        // f(r_c), eq. (4) at the cut-off [pN/μm⁴]
  double cutoff_energy = 0.0;       // φ(r_c), eq. (3) at the cut-off [pN/μm³]

  MorsePotential() = default;
  MorsePotential(double well_depth_, double beta_, double zero_force_length_, double cutoff_)
      : well_depth(well_depth_), beta(beta_), zero_force_length(zero_force_length_), cutoff(cutoff_) {
    cutoff_force = unshifted_force_and_energy(cutoff, cutoff_energy);
  }

  // eq. (4) as f(r), with eq. (3) as φ(r) in `energy`, from one exponential.
  KOKKOS_INLINE_FUNCTION double unshifted_force_and_energy(const double r, double& energy) const {
    const double e = exp(beta * (zero_force_length - r));
    energy = well_depth * (e * e - 2.0 * e);
    return 2.0 * well_depth * beta * (e * e - e);
  }
  KOKKOS_INLINE_FUNCTION double unshifted_energy(const double r) const {
    double energy = 0.0;
    unshifted_force_and_energy(r, energy);
    return energy;
  }
  KOKKOS_INLINE_FUNCTION double unshifted_force(const double r) const {
    double energy = 0.0;
    return unshifted_force_and_energy(r, energy);
  }

  // f_s(r), with φ_s(r) in `energy`, from one exponential.
  KOKKOS_INLINE_FUNCTION double force_and_energy(const double r, double& energy) const {
    const double force = unshifted_force_and_energy(r, energy);
    energy += (r - cutoff) * cutoff_force - cutoff_energy;
    return force - cutoff_force;
  }
  KOKKOS_INLINE_FUNCTION double energy(const double r) const {
    double energy = 0.0;
    force_and_energy(r, energy);
    return energy;
  }
  // f_s(r) = −dφ_s/dr
  KOKKOS_INLINE_FUNCTION double force(const double r) const { return unshifted_force(r) - cutoff_force; }
  // f_s(r), with its slope f_s'(r) = f'(r) = 2 De β² [e^{β(r0−r)} − 2 e^{2β(r0−r)}] [pN/μm⁵]
  // in `slope` (= −φ''(r), the pair's stiffness along the line of centres), from one
  // exponential.
  KOKKOS_INLINE_FUNCTION double force_and_slope(const double r, double& slope) const {
    const double e = exp(beta * (zero_force_length - r));
    slope = 2.0 * well_depth * beta * beta * (e - 2.0 * e * e);
    return 2.0 * well_depth * beta * (e * e - e) - cutoff_force;
  }
};

}  // namespace rouleau
