#pragma once
// Boundary conditions of the fluid domain (a box's six sides, or a vessel's inlet, outlet
// and wall), turned into what the operator needs: Dirichlet unknowns with scaled values,
// and the constant nodal traction load.
#include <Kokkos_Core.hpp>
#include <array>
#include <string>
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

// A boundary condition on the mesh's boundary of that name.
struct FluidBoundary {
  std::string name;
  BoundaryConfig condition;
};

// The box's sides by their names (x_min, ..., z_max); periodic sides are left out (the
// mesh identifies their nodes).
std::vector<FluidBoundary> box_boundaries(const std::array<BoundaryConfig, 6>& sides);

// The boundaries of a case: its box's sides, or its vessel's inlet, outlet and no-slip wall.
std::vector<FluidBoundary> case_boundaries(const CaseConfig& config);

// Walls (no-slip or moving) and inflows give Dirichlet velocities, and traction sides with
// parallel_flow a zero tangential velocity; where sides meet, a wall wins over an inflow,
// which wins over a parallel-flow side. A parabolic inflow on a box side is the product of
// parabolas across its non-periodic tangential directions, on a disc (a vessel's inlet)
// Poiseuille's 2 (1 − r²/R²); both have the requested mean speed. Traction sides give the
// load ∫ N_a (−p n) dA. Inflow and traction need a planar side (an outward normal);
// parallel_flow an axis-aligned one. Without a traction side the pressure is fixed to 0 at
// the first node.
FluidBoundaryConditions build_boundary_conditions(const FluidMesh& mesh, const std::vector<FluidBoundary>& boundaries,
                                                  const FluidScales& scales);
FluidBoundaryConditions build_boundary_conditions(const FluidMesh& mesh,
                                                  const std::array<BoundaryConfig, 6>& sides,
                                                  const FluidScales& scales);

}  // namespace rouleau
