#pragma once
// The divergence-free manufactured solution of the fluid's validation tests and of the
// work–precision study, on the unit cube (k = π, unit scales: μ = 1, L = U = 1):
//   u = (sin kx cos ky cos kz, cos kx sin ky cos kz, −2 cos kx cos ky sin kz),
//   p = sin kx sin ky sin kz,
// with the body force f = Re u·∇u − Δu + ∇p (Δu = −3k² u) that makes it exact.
#include <Kokkos_Core.hpp>
#include <array>
#include <cmath>

#include "mesh/fluid_mesh.hpp"

namespace rouleau {

class FluidSolver;

struct ManufacturedSolution {
  double reynolds = 0.0;
  static constexpr double k = 3.14159265358979323846;

  KOKKOS_INLINE_FUNCTION void operator()(const double x[3], double u[3], double& p) const {
    const double sx = sin(k * x[0]), sy = sin(k * x[1]), sz = sin(k * x[2]);
    const double cx = cos(k * x[0]), cy = cos(k * x[1]), cz = cos(k * x[2]);
    u[0] = sx * cy * cz;
    u[1] = cx * sy * cz;
    u[2] = -2.0 * cx * cy * sz;
    p = sx * sy * sz;
  }
  std::array<double, 3> velocity(const std::array<double, 3>& x) const {
    double u[3], p;
    (*this)(x.data(), u, p);
    return {u[0], u[1], u[2]};
  }
  // f = Re u·∇u + 3k² u + ∇p
  std::array<double, 3> force(const double x[3]) const {
    const double sx = std::sin(k * x[0]), sy = std::sin(k * x[1]), sz = std::sin(k * x[2]);
    const double cx = std::cos(k * x[0]), cy = std::cos(k * x[1]), cz = std::cos(k * x[2]);
    double u[3], p;
    (*this)(x, u, p);
    // ∇u (row i: gradient of u_i)
    const double g[3][3] = {{k * cx * cy * cz, -k * sx * sy * cz, -k * sx * cy * sz},
                            {-k * sx * sy * cz, k * cx * cy * cz, -k * cx * sy * sz},
                            {2 * k * sx * cy * sz, 2 * k * cx * sy * sz, -2 * k * cx * cy * cz}};
    const double grad_p[3] = {k * cx * sy * sz, k * sx * cy * sz, k * sx * sy * cz};
    std::array<double, 3> f;
    for (int i = 0; i < 3; ++i)
      f[i] = reynolds * (u[0] * g[i][0] + u[1] * g[i][1] + u[2] * g[i][2]) + 3.0 * k * k * u[i] + grad_p[i];
    return f;
  }
};

// Prescribes the exact velocity on every boundary node of `mesh` and the body force f at
// every node: the problem whose solution converges to `exact`.
void set_up_manufactured_problem(FluidSolver& solver, const FluidMesh& mesh, const ManufacturedSolution& exact);

}  // namespace rouleau
