#pragma once
// The cells' compressible neo-Hookean solid (paper eq. 2) and its nodal internal forces
// on 4-node tetrahedra in total-Lagrangian form (paper eqs. 9–10), with an optional
// strain-hardening term (Mills, Qie, Dao, Lim & Suresh 2004, the third-order Yeoh term;
// off, C3 = 0, in the paper's scenes):
//
//   W(F) = C1 (J1 − 3) + C3 (J1 − 3)³ + C2/2 (J2 − 1)²,  J1 = I1 I3^(−1/3),  J2 = I3^(1/2),
//   I1 = tr C = F : F,  I3 = det C = J²,  J = det F,  C = FᵀF,
// with C1 = G/2 and C2 = K (small-strain shear and bulk moduli; the C3 term is of fourth
// order in the strain, J1 − 3 ≥ 0 being of second order, so it leaves G and K unchanged)
// and C3 = r G, r the kind's strain_hardening_ratio (Mills et al.: C3 = G/30).
// Its first Piola–Kirchhoff stress P = ∂W/∂F, with ∂I1/∂F = 2F, ∂J/∂F = cof F = J F⁻ᵀ,
// ∂J1/∂F = 2 J^(−2/3) F − (2/3) I1 J^(−5/3) cof F:
//   P = C1' [2 J^(−2/3) F − (2/3) I1 J^(−5/3) cof F] + C2 (J − 1) cof F,
//   C1' = C1 + 3 C3 (J1 − 3)²,
// and the internal (elastic) force on node a of an element, f_a = −∂(V0 W)/∂x_a:
//   f_a = −V0 P ∇_X N_a.
// The element's strain energy is V0 W(F).
#include <Kokkos_Core.hpp>
#include <cmath>

#include "kernels/launch_tags.hpp"
#include "kernels/mat3.hpp"
#include "kernels/tet4.hpp"

namespace rouleau {

struct NeoHookeanMaterial {
  double c1 = 0.0;  // C1 = G/2 [Pa]
  double c2 = 0.0;  // C2 = K [Pa]
  double c3 = 0.0;  // C3 = r G, the strain-hardening coefficient [Pa] (0: the paper's law)

  // From G, K and the strain-hardening ratio r = C3/G (Mills et al. 2004: 1/30).
  static NeoHookeanMaterial from_moduli(double shear_modulus, double bulk_modulus,
                                        double strain_hardening_ratio = 0.0) {
    return {0.5 * shear_modulus, bulk_modulus, strain_hardening_ratio * shear_modulus};
  }

  // The invariants W and P are built from: J = det F, I1 = F : F, J^(−2/3).
  struct Invariants {
    double j, i1, j_minus_two_thirds;
  };
  KOKKOS_INLINE_FUNCTION static Invariants invariants(const Mat3& f) {
    const double j = determinant(f);
    const double cube_root = cbrt(j);
    return {j, frobenius_product(f, f), 1.0 / (cube_root * cube_root)};
  }

  // W(F) = C1 (J1 − 3) + C3 (J1 − 3)³ + C2/2 (J − 1)² [Pa = pN·μm/μm³]
  KOKKOS_INLINE_FUNCTION double energy_density(const Invariants& v) const {
    const double distortion = v.i1 * v.j_minus_two_thirds - 3.0;  // J1 − 3
    return (c1 + c3 * distortion * distortion) * distortion + 0.5 * c2 * (v.j - 1.0) * (v.j - 1.0);
  }
  KOKKOS_INLINE_FUNCTION double energy_density(const Mat3& f) const { return energy_density(invariants(f)); }

  // P(F) = ∂W/∂F = C1' ∂J1/∂F + C2 (J − 1) cof F, C1' = C1 + 3 C3 (J1 − 3)² [Pa]
  KOKKOS_INLINE_FUNCTION Mat3 first_piola(const Mat3& f, const Invariants& v) const {
    const Mat3 cof = cofactor(f);
    const double distortion = v.i1 * v.j_minus_two_thirds - 3.0;  // J1 − 3
    const double c1_effective = c1 + 3.0 * c3 * distortion * distortion;
    const double deviatoric = 2.0 * c1_effective * v.j_minus_two_thirds;
    const double volumetric = -(2.0 / 3.0) * c1_effective * v.i1 * v.j_minus_two_thirds / v.j + c2 * (v.j - 1.0);
    Mat3 p;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) p.m[i][k] = deviatoric * f.m[i][k] + volumetric * cof.m[i][k];
    return p;
  }
  KOKKOS_INLINE_FUNCTION Mat3 first_piola(const Mat3& f) const { return first_piola(f, invariants(f)); }

  // Cauchy stress σ = J⁻¹ P Fᵀ [Pa]
  KOKKOS_INLINE_FUNCTION Mat3 cauchy_stress(const Mat3& f) const {
    Mat3 sigma = multiply(first_piola(f), transpose(f));
    const double inverse_j = 1.0 / determinant(f);
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) sigma.m[i][k] *= inverse_j;
    return sigma;
  }
};

// Internal forces of all tetrahedra of all cells, summed into the nodes through a
// ScatterView; with ForcesAndEnergy also the total strain energy Σ V0 W.
template <class Scatter>
struct NeoHookeanForceFunctor {
  Kokkos::View<const double* [3]> positions;                // x (node, 3) [μm]
  Kokkos::View<const int* [4]> element_nodes;               // (element, 4)
  Kokkos::View<const double* [3][3]> inverse_edge_matrix;   // D_m⁻¹ (element, 3, 3) [1/μm]
  Kokkos::View<const double*> reference_volume;             // V0 (element) [μm³]
  Kokkos::View<const int*> element_material;                // index into materials (element)
  Kokkos::View<const NeoHookeanMaterial*> materials;
  Scatter forces;                                           // f (node, 3) [pN]

  // Forces of element e; with `with_energy`, returns its strain energy V0 W (else 0).
  template <bool with_energy>
  KOKKOS_INLINE_FUNCTION double element_forces(const int e) const {
    double x[4][3];
    Mat3 inverse;
    Tet4::gather(e, positions, element_nodes, inverse_edge_matrix, x, inverse);
    double gradient[4][3];
    Tet4::shape_gradients(inverse, gradient);
    const Mat3 f = Tet4::deformation_gradient(x, inverse);
    const NeoHookeanMaterial material = materials(element_material(e));
    const NeoHookeanMaterial::Invariants invariants = NeoHookeanMaterial::invariants(f);
    const Mat3 p = material.first_piola(f, invariants);
    const double volume = reference_volume(e);
    auto access = forces.access();
    for (int a = 0; a < 4; ++a) {
      const int node = element_nodes(e, a);
      for (int i = 0; i < 3; ++i) {
        // f_a,i = −V0 Σ_j P_ij ∂N_a/∂X_j
        const double f_ai = -volume * (p.m[i][0] * gradient[a][0] + p.m[i][1] * gradient[a][1] +
                                       p.m[i][2] * gradient[a][2]);
        access(node, i) += f_ai;
      }
    }
    return with_energy ? volume * material.energy_density(invariants) : 0.0;
  }

  KOKKOS_INLINE_FUNCTION void operator()(ForcesOnly, const int e) const { element_forces<false>(e); }
  KOKKOS_INLINE_FUNCTION void operator()(ForcesAndEnergy, const int e, double& energy) const {
    energy += element_forces<true>(e);
  }
};

}  // namespace rouleau
