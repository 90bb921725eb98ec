#include "fluid/boundary_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "fluid/flow_rates.hpp"

namespace rouleau {

std::vector<FluidBoundary> box_boundaries(const std::array<BoundaryConfig, 6>& sides) {
  std::vector<FluidBoundary> boundaries;
  for (int side = 0; side < 6; ++side)
    if (sides[side].type != BoundaryType::periodic) boundaries.push_back({side_names[side], sides[side]});
  return boundaries;
}

std::vector<FluidBoundary> case_boundaries(const CaseConfig& config) {
  if (!config.vessel.enabled) return box_boundaries(config.domain.boundary);
  return {{"inlet", config.vessel.inlet}, {"outlet", config.vessel.outlet}, {"wall", BoundaryConfig{}}};
}

FluidBoundaryConditions build_boundary_conditions(const FluidMesh& mesh, const std::array<BoundaryConfig, 6>& sides,
                                                  const FluidScales& scales) {
  return build_boundary_conditions(mesh, box_boundaries(sides), scales);
}

namespace {
// The axis a planar side's outward normal points along, −1 when it is not axis-aligned.
int normal_axis(const BoundaryFaces& b) {
  for (int d = 0; d < 3; ++d)
    if (std::abs(std::abs(b.outward_normal[d]) - 1.0) < 1e-12) return d;
  return -1;
}
bool is_planar(const BoundaryFaces& b) {
  return b.outward_normal[0] != 0.0 || b.outward_normal[1] != 0.0 || b.outward_normal[2] != 0.0;
}
}  // namespace

FluidBoundaryConditions build_boundary_conditions(const FluidMesh& mesh, const std::vector<FluidBoundary>& boundaries,
                                                  const FluidScales& scales) {
  FluidBoundaryConditions bc;
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const int num_unknowns = mesh.num_unknowns();
  for (const FluidBoundary& boundary : boundaries) {
    const BoundaryFaces& b = mesh.boundary(boundary.name);
    const BoundaryType type = boundary.condition.type;
    if ((type == BoundaryType::inflow || type == BoundaryType::traction) && !is_planar(b))
      throw std::invalid_argument("rouleau::build_boundary_conditions: boundary '" + boundary.name +
                                  "' is not planar; inflow and traction need a planar side");
    if (type == BoundaryType::traction && boundary.condition.parallel_flow && normal_axis(b) < 0)
      throw std::invalid_argument("rouleau::build_boundary_conditions: boundary '" + boundary.name +
                                  "' is not normal to an axis; parallel_flow needs one that is");
    if (type == BoundaryType::periodic)
      throw std::invalid_argument("rouleau::build_boundary_conditions: boundary '" + boundary.name +
                                  "' is periodic; the mesh identifies periodic sides");
  }

  // Velocity constraints per unknown; sides applied by increasing priority (inflow, then wall).
  std::map<int, double> constrained;
  auto apply = [&](const FluidBoundary& boundary) {
    const BoundaryConfig& s = boundary.condition;
    const BoundaryFaces& b = mesh.boundary(boundary.name);
    const int normal = normal_axis(b);
    for (int node : b.nodes) {
      double velocity[3] = {0.0, 0.0, 0.0};
      if (s.type == BoundaryType::wall)
        for (int d = 0; d < 3; ++d) velocity[d] = s.velocity[d];
      if (s.type == BoundaryType::inflow) {
        // Inflow runs against the outward normal, its profile scaled to mean 1:
        //   disc: 2 (1 − r²/R²);  box side: Π 4 s (1 − s) / (2/3) per bounded tangential direction.
        double shape = 1.0;
        if (s.profile == InflowProfile::parabolic && b.disc_radius > 0.0) {
          double r2 = 0.0;
          for (int d = 0; d < 3; ++d) {
            const double offset = coordinates(node, d) - b.disc_center[d];
            const double along_normal = offset * b.outward_normal[d];
            r2 += offset * offset - along_normal * along_normal;
          }
          shape = std::max(0.0, 2.0 * (1.0 - r2 / (b.disc_radius * b.disc_radius)));
        } else if (s.profile == InflowProfile::parabolic) {
          for (int t = 0; t < 3; ++t) {
            if (t == normal || mesh.periodic[t]) continue;
            const double x = (coordinates(node, t) - mesh.lower[t]) / (mesh.upper[t] - mesh.lower[t]);
            shape *= 4.0 * x * (1.0 - x) * 1.5;
          }
        }
        for (int d = 0; d < 3; ++d) velocity[d] = -b.outward_normal[d] * s.mean_speed * shape;
      }
      const int dof_node = mesh.dof_node_of_node[node];
      for (int c = 0; c < 3; ++c) {
        // A parallel-flow traction side fixes only the tangential components (to 0).
        if (s.type == BoundaryType::traction && c == normal) continue;
        constrained[fluid_unknowns_per_node * dof_node + c] = velocity[c] / scales.velocity;
      }
    }
  };
  for (BoundaryType pass : {BoundaryType::traction, BoundaryType::inflow, BoundaryType::wall})
    for (const FluidBoundary& boundary : boundaries)
      if (boundary.condition.type == pass && (pass != BoundaryType::traction || boundary.condition.parallel_flow))
        apply(boundary);

  // Traction load: ∫ N_a dA over each planar face, A/4 at a quadrilateral's corners and
  // A/3 at a triangle's (faces of tetrahedra repeat their last node).
  bc.traction_load = Kokkos::View<double*>("rouleau::FluidBoundaryConditions::traction_load", num_unknowns);
  auto load = Kokkos::create_mirror_view(bc.traction_load);
  bool has_traction = false;
  const BoundaryIntegrals integrals(mesh);
  for (const FluidBoundary& boundary : boundaries) {
    if (boundary.condition.type != BoundaryType::traction) continue;
    has_traction = true;
    const BoundaryFaces& b = mesh.boundary(boundary.name);
    const double pressure = boundary.condition.pressure / scales.pressure;
    const std::vector<double>& areas = integrals.face_areas(boundary.name);
    for (std::size_t k = 0; k < b.faces.size(); ++k) {
      const auto& f = b.faces[k];
      const double area = areas[k] / (scales.length * scales.length);  // scaled
      const int corners = f[3] == f[2] ? 3 : 4;
      for (int corner = 0; corner < corners; ++corner) {
        const int dof_node = mesh.dof_node_of_node[f[corner]];
        for (int d = 0; d < 3; ++d)
          load(fluid_unknowns_per_node * dof_node + d) += -pressure * b.outward_normal[d] * area / corners;
      }
    }
  }
  Kokkos::deep_copy(bc.traction_load, load);

  if (!has_traction) {
    bc.pressure_pinned = true;
    constrained[3] = 0.0;  // pressure of dof node 0
  }
  for (const auto& [dof, value] : constrained) {
    bc.dirichlet_dofs.push_back(dof);
    bc.dirichlet_values.push_back(value);
  }
  return bc;
}

}  // namespace rouleau
