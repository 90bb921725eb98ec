#pragma once
// Boundary conditions of the box fluid domain, turned into what the operator needs:
// Dirichlet unknowns with scaled values, and the constant nodal traction load.
#include <Kokkos_Core.hpp>
#include <array>
#include <vector>

#include "config/case_config.hpp"
#include "mesh/fluid_mesh.hpp"

namespace rouleau {

// Length [μm], velocity [μm/s] and pressure [Pa] scales of the solver's variables.
struct FluidScales {
  double length = 1.0;
  double velocity = 1.0;
  double pressure = 1.0;  // μU/L
  double reynolds = 0.0;  // ρUL/μ
  // Scaled nodal force from a force in pN: F / (P L²).
  double force() const { return pressure * length * length; }
  // Scaled body force from a force density in pN/μm³: f L / P.
  double body_force() const { return pressure / length; }
};

struct FluidBoundaryConditions {
  std::vector<int> dirichlet_dofs;        // unknown indices (4·dof_node + c)
  std::vector<double> dirichlet_values;   // scaled
  bool pressure_pinned = false;           // no traction side: p = 0 at one node fixes the constant
  Kokkos::View<double*> traction_load;    // scaled nodal load ∫ N_a t dA, t = −p n
};

// Walls (no-slip or moving) and inflows give Dirichlet velocities, and traction sides with
// parallel_flow a zero tangential velocity; where sides meet, a wall wins over an inflow,
// which wins over a parallel-flow side. A parabolic inflow is the product of parabolas across the
// face's non-periodic tangential directions, scaled to the requested mean speed.
// Traction sides give the load ∫ N_a (−p n) dA. Without a traction side the pressure is
// fixed to 0 at the first node.
FluidBoundaryConditions build_boundary_conditions(const FluidMesh& mesh,
                                                  const std::array<BoundaryConfig, 6>& sides,
                                                  const FluidScales& scales);

}  // namespace rouleau
