#pragma once
// Flow rates and mean pressures of a fluid solution over boundaries and cross-sections,
// integrated exactly for the piecewise-linear (tetrahedra) or bilinear-on-faces (hexahedra)
// fields: the vessel diagnostics (driving pressure, flow rate), the traction loads and the
// conservation tests.
#include <map>
#include <string>
#include <vector>

#include "mesh/fluid_mesh.hpp"

namespace rouleau {

// The boundary faces' areas, computed once from the mesh (a host copy of its coordinates),
// and the integrals of nodal fields over them: ∫ f dA = Σ_faces A Σ_corners f / corners,
// exact for f linear on triangles (A/3 per corner) and bilinear on parallelogram
// quadrilaterals (A/4 per corner). The mesh must outlive it.
class BoundaryIntegrals {
 public:
  explicit BoundaryIntegrals(const FluidMesh& mesh);

  // The area [μm²] of each face of the boundary `name`, in the order of its faces.
  const std::vector<double>& face_areas(const std::string& name) const;
  // Its whole area [μm²].
  double area(const std::string& name) const;
  // ∫ u·n dA [μm³/s], n outward (negative where fluid enters); `velocity`: 3 per geometric
  // node [μm/s] (FluidSolver::velocity_and_pressure). Needs a planar boundary.
  double flow_rate(const std::vector<double>& velocity, const std::string& name) const;
  // ∫ p dA / ∫ dA [Pa]; `pressure`: one per geometric node.
  double mean_pressure(const std::vector<double>& pressure, const std::string& name) const;

 private:
  template <class Field>
  double integral(const std::string& name, const Field& f) const;

  const FluidMesh& mesh_;
  std::map<std::string, std::vector<double>> face_areas_;
};

// ∫ u_axis dA over the cross-section {x_axis = position} of a tetrahedral mesh [μm³/s]:
// each tetrahedron the plane cuts contributes its section (a triangle or a quadrilateral),
// on which the linear u_axis is integrated exactly. Throws for a hexahedral mesh.
double cross_section_flow_rate(const FluidMesh& mesh, const std::vector<double>& velocity, int axis,
                               double position);

}  // namespace rouleau
