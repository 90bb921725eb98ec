// What a caller prescribes to the fluid solver: the body force density, an initial
// velocity field, and the velocity on the Dirichlet boundary (fluid/fluid_solver.hpp).
#include "fluid/fluid_solver.hpp"

namespace rouleau {

void FluidSolver::set_body_force(const std::vector<double>& force_density) {
  const int nodes = mesh_.num_dof_nodes;
  Vector global("rouleau::FluidSolver::body_force_global", num_global_unknowns_);
  auto host = Kokkos::create_mirror_view(global);
  const double scale = 1.0 / scales_.body_force();
  for (int i = 0; i < nodes; ++i)
    for (int d = 0; d < 3; ++d) host(4 * i + d) = force_density[3 * i + d] * scale;
  Kokkos::deep_copy(global, host);
  exchange_->localize(global, body_force_);
}

void FluidSolver::set_uniform_body_force(const std::array<double, 3>& force_density) {
  std::vector<double> field(3 * mesh_.num_dof_nodes);
  for (size_t i = 0; i < field.size(); ++i) field[i] = force_density[i % 3];
  set_body_force(field);
}

void FluidSolver::set_velocity(
    const std::function<std::array<double, 3>(const std::array<double, 3>&)>& velocity) {
  const FluidMesh& mesh = operator_.mesh();
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto state = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), state_);
  for (int n = 0; n < mesh.num_nodes; ++n) {
    const auto v = velocity({coordinates(n, 0), coordinates(n, 1), coordinates(n, 2)});
    for (int c = 0; c < 3; ++c) state(4 * mesh.dof_node_of_node[n] + c) = v[c] / scales_.velocity;
  }
  Kokkos::deep_copy(state_, state);
  operator_.impose_dirichlet(state_);
}

void FluidSolver::prescribe_boundary_velocity(
    const std::function<std::array<double, 3>(const std::array<double, 3>&)>& velocity) {
  const FluidMesh& mesh = operator_.mesh();
  auto coordinates = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  std::vector<int> node_of_dof_node(mesh.num_dof_nodes, -1);
  for (int n = 0; n < mesh.num_nodes; ++n)
    if (node_of_dof_node[mesh.dof_node_of_node[n]] < 0) node_of_dof_node[mesh.dof_node_of_node[n]] = n;
  for (size_t k = 0; k < boundary_.dirichlet_dofs.size(); ++k) {
    const int dof = boundary_.dirichlet_dofs[k], component = dof % 4;
    if (component == 3) continue;
    const int node = node_of_dof_node[dof / 4];
    const auto v = velocity({coordinates(node, 0), coordinates(node, 1), coordinates(node, 2)});
    boundary_.dirichlet_values[k] = v[component] / scales_.velocity;
  }
  operator_.set_dirichlet(boundary_.dirichlet_dofs, boundary_.dirichlet_values);
  operator_.impose_dirichlet(state_);
}

}  // namespace rouleau
