#include "fluid/manufactured_solution.hpp"

#include <vector>

#include "fluid/fluid_solver.hpp"

namespace rouleau {

void set_up_manufactured_problem(FluidSolver& solver, const FluidMesh& mesh, const ManufacturedSolution& exact) {
  solver.prescribe_boundary_velocity([&](const std::array<double, 3>& x) { return exact.velocity(x); });
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  std::vector<double> force(3 * mesh.num_dof_nodes);
  for (int node = 0; node < mesh.num_nodes; ++node) {
    const double x[3] = {coordinates(node, 0), coordinates(node, 1), coordinates(node, 2)};
    const auto f = exact.force(x);
    for (int d = 0; d < 3; ++d) force[3 * mesh.dof_node_of_node[node] + d] = f[d];
  }
  solver.set_body_force(force);
}

}  // namespace rouleau
