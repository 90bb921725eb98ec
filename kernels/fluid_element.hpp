#pragma once
// The stabilized equal-order Navier–Stokes element (paper eqs. 13–14) in scaled variables.
//
// Scaled with a length L, a velocity U and the pressure scale μU/L, the momentum and
// continuity equations read
//     Re (∂u/∂t + c u·∇u) + ∇p − ∇·(∇u + ∇uᵀ) = f,      ∇·u = 0,      Re = ρUL/μ,
// with c = 1 (Navier–Stokes) or 0 (the Stokes limit). The weak residual at node a,
// component i, summed over elements, is
//   R_ai = ∫ N_a Re (u_t + c u·∇u)_i + ∂_j N_a (∂_j u_i + ∂_i u_j) − ∂_i N_a p − N_a f_i
//          + Re τ_M (c u·∇N_a) r_i                       (SUPG)
//          + ν_L ∂_i N_a ∇·u                              (LSIC)
//   R_a4 = ∫ N_a ∇·u + τ_M ∇N_a · r                       (continuity + PSPG)
// where r = Re (u_t + c u·∇u) + ∇p − ∇·(G + Gᵀ) − f is the strong momentum residual.
// Its viscous term needs second derivatives that linear and trilinear elements do not
// have; G is the velocity gradient projected onto the nodes (lumped L2 projection), so
// ∇·(G + Gᵀ) is a consistent O(h) approximation of Δu + ∇(∇·u) (Jansen, Collis, Whiting &
// Shakib 1999). Without it (viscous_reconstruction = 0) SUPG is inconsistent at O(h) and
// costs the pressure its accuracy. And
//   τ_M = τ/Re = [ (2 Re/Δt)² + (2 Re |u|/h)² + (4/h²)² ]^(−1/2)       (Tezduyar 1992)
//   ν_L = Re (h/2)|u| min(1, Re_h/3),  Re_h = Re |u| h / 2.
// τ_M and ν_L are evaluated from a frozen velocity and are not differentiated.
// The time derivative is u_t = m u + H with m = α0/Δt and H the history part of BDF.
#include <Kokkos_Core.hpp>
#include <cmath>
#include <type_traits>

#include "kernels/dual.hpp"

namespace rouleau {

struct FluidCoefficients {
  double reynolds = 0.0;          // Re = ρUL/μ
  double mass_coefficient = 0.0;  // α0/Δt (scaled); 0 for a steady solve
  double inverse_dt = 0.0;        // 1/Δt (scaled) in τ; 0 for a steady solve
  int convection = 1;             // 1: Navier–Stokes, 0: Stokes limit
  int lsic = 1;                   // grad-div (LSIC) stabilization on/off
  int viscous_reconstruction = 0;  // viscous term of r from the projected gradient G
};

// τ_M = [ (2 Re/Δt)² + (2 Re |u|/h)² + (4/h²)² ]^(−1/2)
KOKKOS_INLINE_FUNCTION double stabilization_tau(const FluidCoefficients& c, double speed, double h) {
  const double transient = 2.0 * c.reynolds * c.inverse_dt;
  const double advective = c.convection * 2.0 * c.reynolds * speed / h;
  const double viscous = 4.0 / (h * h);
  return 1.0 / sqrt(transient * transient + advective * advective + viscous * viscous);
}

// ν_L = Re (h/2)|u| min(1, Re_h/3),  Re_h = Re |u| h/2
KOKKOS_INLINE_FUNCTION double lsic_coefficient(const FluidCoefficients& c, double speed, double h) {
  if (!c.convection || !c.lsic) return 0.0;
  const double cell_reynolds = 0.5 * c.reynolds * speed * h;
  const double limiter = cell_reynolds / 3.0 < 1.0 ? cell_reynolds / 3.0 : 1.0;
  return c.reynolds * 0.5 * h * speed * limiter;
}

// Per element and quadrature point, `geometry(e, q, 3k+d)` holds ∂ξ_k/∂x_d and
// `geometry(e, q, 9)` holds det(∂x/∂ξ)·w_q.
inline constexpr int geometry_entries = 10;

// The shape functions N_a and their gradients ∇N_a = Σ_k ∂N_a/∂ξ_k ∂ξ_k/∂x at element
// e's quadrature point q, from the stored geometry.
template <class Element, class GeometryView>
KOKKOS_INLINE_FUNCTION void shape_functions_at(const GeometryView& geometry, const int e, const int q,
                                               double (&shape)[Element::nodes],
                                               double (&grad)[Element::nodes][3]) {
  double xi[3];
  Element::quadrature_point(q, xi);
  for (int a = 0; a < Element::nodes; ++a) {
    shape[a] = Element::shape(a, xi);
    double ref[3];
    for (int k = 0; k < 3; ++k) ref[k] = Element::shape_gradient(a, k, xi);
    for (int d = 0; d < 3; ++d)
      grad[a][d] = ref[0] * geometry(e, q, d) + ref[1] * geometry(e, q, 3 + d) + ref[2] * geometry(e, q, 6 + d);
  }
}

// The viscous term of the strong residual from the projected gradient G (zero when
// coef.viscous_reconstruction is off):  ∇·(G + Gᵀ)_i = Σ_a Σ_j ∂_j N_a (G_a,ij + G_a,ji).
template <int Nodes, class Scalar>
KOKKOS_INLINE_FUNCTION void projected_viscous_divergence(const FluidCoefficients& coef, const double (&grad)[Nodes][3],
                                                         const Scalar* gradient, Scalar (&divergence)[3]) {
  for (int i = 0; i < 3; ++i) divergence[i] = 0.0;
  if (!coef.viscous_reconstruction) return;
  for (int a = 0; a < Nodes; ++a)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) divergence[i] += grad[a][j] * (gradient[9 * a + 3 * i + j] + gradient[9 * a + 3 * j + i]);
}

// Adds the element residual R_a (see the header comment) to `residual`, by quadrature
// (every element; fluid_element_residual() below takes a closed form where it can).
//   state(a, 0..3)   nodal u, v, w, p (Scalar: double, or Dual for derivatives)
//   frozen(a, 0..2)  nodal velocity from which τ_M and ν_L are computed
//   history(a, 0..2) nodal BDF history H;  force(a, 0..2) nodal body force f
//   gradient         nodal projected velocity gradient G_a (9 per node, G_a[3i+j] = ∂_j u_i),
//                    read when coef.viscous_reconstruction is on (else may be null)
//   subscale         when not null: subscale[a][i] += ∫ N_a τ_M r_i dV, the moments of
//                    PSPG's subscale velocity u' = −τ_M r (FluidSubscaleFunctor; in dual
//                    numbers their derivative along a direction, FluidSubscaleActionFunctor)
template <class Element, class Scalar, class GeometryView>
KOKKOS_INLINE_FUNCTION void fluid_element_residual_by_quadrature(
    const FluidCoefficients& coef, const GeometryView& geometry, const int e, const double h,
    const Scalar (&state)[Element::nodes][4], const double (&frozen)[Element::nodes][3],
    const double (&history)[Element::nodes][3], const double (&force)[Element::nodes][3],
    const Scalar* gradient, Scalar (&residual)[Element::nodes][4], Scalar (*subscale)[3] = nullptr) {
  constexpr int n = Element::nodes;
  const double re = coef.reynolds;
  for (int q = 0; q < Element::quadrature_points; ++q) {
    double shape[n], grad[n][3];
    shape_functions_at<Element>(geometry, e, q, shape, grad);
    const double dv = geometry(e, q, 9);

    // Values at the quadrature point.
    Scalar u[3], grad_u[3][3], p, grad_p[3];
    double frozen_u[3] = {0, 0, 0}, history_u[3] = {0, 0, 0}, f[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
      u[i] = 0.0;
      grad_p[i] = 0.0;
      for (int j = 0; j < 3; ++j) grad_u[i][j] = 0.0;
    }
    p = 0.0;
    for (int a = 0; a < n; ++a) {
      for (int i = 0; i < 3; ++i) {
        u[i] += shape[a] * state[a][i];
        frozen_u[i] += shape[a] * frozen[a][i];
        history_u[i] += shape[a] * history[a][i];
        f[i] += shape[a] * force[a][i];
        for (int j = 0; j < 3; ++j) grad_u[i][j] += grad[a][j] * state[a][i];
        grad_p[i] += grad[a][i] * state[a][3];
      }
      p += shape[a] * state[a][3];
    }
    const double speed = sqrt(frozen_u[0] * frozen_u[0] + frozen_u[1] * frozen_u[1] + frozen_u[2] * frozen_u[2]);
    const double tau = stabilization_tau(coef, speed, h);
    const double nu_lsic = lsic_coefficient(coef, speed, h);

    Scalar viscous_divergence[3];
    projected_viscous_divergence<n>(coef, grad, gradient, viscous_divergence);

    // Inertia Re (u_t + c u·∇u) and the strong residual r = inertia + ∇p − ∇·(G + Gᵀ) − f.
    Scalar inertia[3], strong[3];
    for (int i = 0; i < 3; ++i) {
      Scalar acceleration = coef.mass_coefficient * u[i] + history_u[i];
      if (coef.convection)
        acceleration += u[0] * grad_u[i][0] + u[1] * grad_u[i][1] + u[2] * grad_u[i][2];
      inertia[i] = re * acceleration;
      strong[i] = inertia[i] + grad_p[i] - viscous_divergence[i] - f[i];
    }
    const Scalar divergence = grad_u[0][0] + grad_u[1][1] + grad_u[2][2];

    // Flux form: every term above is N_a s_c + ∇N_a · F_c with, per quadrature point,
    //   s_i = Re (u_t + c u·∇u)_i − f_i,        s_4 = ∇·u
    //   F_ij = ∂_j u_i + ∂_i u_j − p δ_ij + ν_L ∇·u δ_ij + Re τ_M c u_j r_i,   F_4j = τ_M r_j
    // (SUPG: (u·∇N_a) r_i = ∇N_a · (u r_i); PSPG: τ_M ∇N_a · r), so each node costs 16
    // multiply-adds instead of re-forming the terms.
    Scalar source[4], flux[4][3];
    const Scalar pressure_and_lsic = nu_lsic * divergence - p;
    for (int i = 0; i < 3; ++i) {
      source[i] = dv * (inertia[i] - f[i]);
      const Scalar supg = coef.convection ? Scalar((re * tau) * strong[i]) : Scalar(0.0);
      for (int j = 0; j < 3; ++j) {
        Scalar fij = grad_u[i][j] + grad_u[j][i];
        if (coef.convection) fij += supg * u[j];
        if (i == j) fij += pressure_and_lsic;
        flux[i][j] = dv * fij;
      }
      flux[3][i] = (dv * tau) * strong[i];
    }
    source[3] = dv * divergence;
    if (subscale)
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < 3; ++i) subscale[a][i] += shape[a] * flux[3][i];
    for (int a = 0; a < n; ++a)
      for (int c = 0; c < 4; ++c)
        residual[a][c] += shape[a] * source[c] + grad[a][0] * flux[c][0] + grad[a][1] * flux[c][1] +
                          grad[a][2] * flux[c][2];
  }
}

// The volume V and the constant shape-function gradients ∇N_a of an affine element
// (Element::affine: ∂ξ/∂x the same at every quadrature point and equal weights, so the
// first point's stored geometry is the whole element's).
template <class Element, class GeometryView>
KOKKOS_INLINE_FUNCTION double affine_element_gradients(const GeometryView& geometry, const int e,
                                                       double (&grad)[Element::nodes][3]) {
  static_assert(Element::affine, "only an affine element has constant shape-function gradients");
  const double xi[3] = {0.25, 0.25, 0.25};
  for (int a = 0; a < Element::nodes; ++a)
    for (int d = 0; d < 3; ++d)
      grad[a][d] = Element::shape_gradient(a, 0, xi) * geometry(e, 0, d) +
                   Element::shape_gradient(a, 1, xi) * geometry(e, 0, 3 + d) +
                   Element::shape_gradient(a, 2, xi) * geometry(e, 0, 6 + d);
  return Element::quadrature_points * geometry(e, 0, 9);
}

// The same residual in closed form, for an affine element (the linear tetrahedron) in the
// Stokes limit (c = 0). Then τ_M depends on h and Δt alone, ν_L = 0, and every term is a
// linear field g integrated against N_a or ∇N_a, which the linear tetrahedron integrates
// exactly (as its degree-2 rule does):
//   ∫ N_a dV = V/4,   ∫ N_a N_b dV = V (1 + δ_ab)/20,  so  ∫ N_a g dV = V (g_a + 4 ḡ)/20,
//   ∫ ∇N_a · F dV = V ∇N_a · F̄,
// with g_a the nodal values and ḡ their mean, the value at the centroid. So, with the
// source s = Re (m u + H) − f and the strong residual r = s + ∇p − ∇·(G + Gᵀ) at the nodes,
//   R_ai = V (s_ai + 4 s̄_i)/20 + V Σ_j ∂_j N_a (∂_j u_i + ∂_i u_j − p̄ δ_ij)
//   R_a4 = V/4 ∇·u + V τ_M ∇N_a · r̄,      subscale_ai += V τ_M (r_ai + 4 r̄_i)/20,
// one pass over the nodes instead of one per quadrature point.
template <class Element, class Scalar, class GeometryView>
KOKKOS_INLINE_FUNCTION void fluid_element_residual_affine_stokes(
    const FluidCoefficients& coef, const GeometryView& geometry, const int e, const double h,
    const Scalar (&state)[Element::nodes][4], const double (&history)[Element::nodes][3],
    const double (&force)[Element::nodes][3], const Scalar* gradient, Scalar (&residual)[Element::nodes][4],
    Scalar (*subscale)[3] = nullptr) {
  constexpr int n = Element::nodes;
  constexpr double mean = 1.0 / n;
  double grad[n][3];
  const double volume = affine_element_gradients<Element>(geometry, e, grad);
  const double tau = stabilization_tau(coef, 0.0, h);  // no convective part: |u| does not enter
  const double re = coef.reynolds;

  Scalar grad_u[3][3], grad_p[3], p_mean = 0.0;
  for (int i = 0; i < 3; ++i) {
    grad_p[i] = 0.0;
    for (int j = 0; j < 3; ++j) grad_u[i][j] = 0.0;
  }
  for (int a = 0; a < n; ++a) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) grad_u[i][j] += grad[a][j] * state[a][i];
      grad_p[i] += grad[a][i] * state[a][3];
    }
    p_mean += mean * state[a][3];
  }
  Scalar viscous_divergence[3];  // constant on the element
  projected_viscous_divergence<n>(coef, grad, gradient, viscous_divergence);

  // s_ai = Re (m u_ai + H_ai) − f_ai at the nodes, and its mean.
  Scalar source[n][3], source_mean[3];
  for (int i = 0; i < 3; ++i) source_mean[i] = 0.0;
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i) {
      source[a][i] = re * (coef.mass_coefficient * state[a][i] + history[a][i]) - force[a][i];
      source_mean[i] += mean * source[a][i];
    }
  // r̄ = s̄ + ∇p − ∇·(G + Gᵀ), and V F̄_ij = V (∂_j u_i + ∂_i u_j − p̄ δ_ij)
  Scalar strong_mean[3], flux[3][3];
  for (int i = 0; i < 3; ++i) {
    strong_mean[i] = source_mean[i] + grad_p[i] - viscous_divergence[i];
    for (int j = 0; j < 3; ++j) flux[i][j] = volume * (grad_u[i][j] + grad_u[j][i]);
    flux[i][i] -= volume * p_mean;
  }
  const Scalar divergence_share = (0.25 * volume) * (grad_u[0][0] + grad_u[1][1] + grad_u[2][2]);
  const double mass_share = volume / 20.0;
  for (int a = 0; a < n; ++a) {
    for (int i = 0; i < 3; ++i)
      residual[a][i] += mass_share * (source[a][i] + 4.0 * source_mean[i]) + grad[a][0] * flux[i][0] +
                        grad[a][1] * flux[i][1] + grad[a][2] * flux[i][2];
    residual[a][3] += divergence_share + (volume * tau) * (grad[a][0] * strong_mean[0] + grad[a][1] * strong_mean[1] +
                                                           grad[a][2] * strong_mean[2]);
  }
  if (subscale)
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < 3; ++i) {
        // r_ai − r̄_i = s_ai − s̄_i: ∇p and the viscous term are constant on the element
        const Scalar strong_at_node = strong_mean[i] + source[a][i] - source_mean[i];
        subscale[a][i] += (mass_share * tau) * (strong_at_node + 4.0 * strong_mean[i]);
      }
}

// Adds the element residual R_a (see the header comment) to `residual`; the arguments are
// those of fluid_element_residual_by_quadrature. Affine elements in the Stokes limit take the
// closed form, the same to round-off (FluidElement test in tests/test_fluid_operator.cpp);
// the vessels' operator applies 3.1–3.5 times faster with it (bench/scenes.md).
template <class Element, class Scalar, class GeometryView>
KOKKOS_INLINE_FUNCTION void fluid_element_residual(
    const FluidCoefficients& coef, const GeometryView& geometry, const int e, const double h,
    const Scalar (&state)[Element::nodes][4], const double (&frozen)[Element::nodes][3],
    const double (&history)[Element::nodes][3], const double (&force)[Element::nodes][3],
    const Scalar* gradient, Scalar (&residual)[Element::nodes][4], Scalar (*subscale)[3] = nullptr) {
  if constexpr (Element::affine) {
    if (!coef.convection) {
      fluid_element_residual_affine_stokes<Element, Scalar>(coef, geometry, e, h, state, history, force, gradient,
                                                            residual, subscale);
      return;
    }
  }
  fluid_element_residual_by_quadrature<Element, Scalar>(coef, geometry, e, h, state, frozen, history, force,
                                                        gradient, residual, subscale);
}

// The stabilization's share of the immersed nodal loads b (paper eq. 16). The loads enter
// the Galerkin momentum rows as they are, R_ai −= b_ai (the exact transpose of RKPM
// interpolation); their force density, interpolated from the nodes,
//     f_h = Σ_b N_b b_b / m_b,      m_b = ∫ N_b dV (the lumped mass),
// is the −f of the strong residual r that SUPG and PSPG weight, as a body force is:
//     R_ai += −Re τ_M c (u·∇N_a) f_h,i          (SUPG)
//     R_a4 += −τ_M ∇N_a · f_h                   (PSPG)
// Without it, r holds the pressure gradient that balances a cell's membrane force but not
// the force, and PSPG's term τ_M ∇N_a·∇p carries a Darcy-like flux τ_M ∇p (scaled)
// through the membrane (tests/test_fluid_flows.cpp, a pressurized shell at rest).
//   frozen(a, 0..2)  nodal velocity for τ_M and the SUPG weight (neither differentiated)
//   density(a, 0..2) nodal force density b_a / m_a (scaled)
//   subscale         when not null: subscale[a][i] += ∫ N_a τ_M (−f_h,i) dV, the loads' share
//                    of the subscale velocity's moments (fluid_element_residual)
// An affine element in the Stokes limit takes the closed form (as fluid_element_residual):
//   R_a4 −= V τ_M ∇N_a · f̄_h,   subscale_ai −= V τ_M (f_h,ai + 4 f̄_h,i)/20.
template <class Element, class GeometryView>
KOKKOS_INLINE_FUNCTION void fluid_element_load_stabilization(
    const FluidCoefficients& coef, const GeometryView& geometry, const int e, const double h,
    const double (&frozen)[Element::nodes][3], const double (&density)[Element::nodes][3],
    double (&residual)[Element::nodes][4], double (*subscale)[3] = nullptr) {
  constexpr int n = Element::nodes;
  if constexpr (Element::affine) {
    if (!coef.convection) {
      double grad[n][3], mean_density[3] = {0, 0, 0};
      const double volume = affine_element_gradients<Element>(geometry, e, grad);
      const double tau_volume = stabilization_tau(coef, 0.0, h) * volume;
      for (int a = 0; a < n; ++a)
        for (int i = 0; i < 3; ++i) mean_density[i] += density[a][i] / n;
      for (int a = 0; a < n; ++a) {
        residual[a][3] -= tau_volume * (grad[a][0] * mean_density[0] + grad[a][1] * mean_density[1] +
                                        grad[a][2] * mean_density[2]);
        if (subscale)
          for (int i = 0; i < 3; ++i) subscale[a][i] -= (tau_volume / 20.0) * (density[a][i] + 4.0 * mean_density[i]);
      }
      return;
    }
  }
  for (int q = 0; q < Element::quadrature_points; ++q) {
    double shape[n], grad[n][3];
    shape_functions_at<Element>(geometry, e, q, shape, grad);
    const double dv = geometry(e, q, 9);
    double u[3] = {0, 0, 0}, f[3] = {0, 0, 0};
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < 3; ++i) {
        u[i] += shape[a] * frozen[a][i];
        f[i] += shape[a] * density[a][i];
      }
    const double speed = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double tau_dv = stabilization_tau(coef, speed, h) * dv;
    for (int a = 0; a < n; ++a) {
      if (subscale)
        for (int i = 0; i < 3; ++i) subscale[a][i] -= shape[a] * tau_dv * f[i];
      residual[a][3] -= tau_dv * (grad[a][0] * f[0] + grad[a][1] * f[1] + grad[a][2] * f[2]);
      if (coef.convection) {
        const double weight = coef.reynolds * tau_dv * (u[0] * grad[a][0] + u[1] * grad[a][1] + u[2] * grad[a][2]);
        for (int i = 0; i < 3; ++i) residual[a][i] -= weight * f[i];
      }
    }
  }
}

}  // namespace rouleau
