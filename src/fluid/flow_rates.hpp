#pragma once
// Flow rates and mean pressures of a fluid solution over boundaries and cross-sections,
// integrated exactly for the piecewise-linear (tetrahedra) or bilinear-on-faces (hexahedra)
// fields: the vessel diagnostics (driving pressure, flow rate) and the conservation tests.
#include <string>
#include <vector>

#include "mesh/fluid_mesh.hpp"

namespace rouleau {

// ∫ u·n dA over the boundary `name` [μm³/s], n outward (negative where fluid enters).
// `velocity`: 3 per geometric node [μm/s] (FluidSolver::velocity_and_pressure). Needs a
// planar boundary.
double boundary_flow_rate(const FluidMesh& mesh, const std::vector<double>& velocity, const std::string& name);

// The area-weighted mean ∫ p dA / ∫ dA over the boundary `name` [Pa]; `pressure`: one per
// geometric node.
double boundary_mean_pressure(const FluidMesh& mesh, const std::vector<double>& pressure, const std::string& name);

// The area of the boundary `name` [μm²].
double boundary_area(const FluidMesh& mesh, const std::string& name);

// ∫ u_axis dA over the cross-section {x_axis = position} of a tetrahedral mesh [μm³/s]:
// each tetrahedron the plane cuts contributes its section (a triangle or a quadrilateral),
// on which the linear u_axis is integrated exactly. Throws for a hexahedral mesh.
double cross_section_flow_rate(const FluidMesh& mesh, const std::vector<double>& velocity, int axis,
                               double position);

}  // namespace rouleau
