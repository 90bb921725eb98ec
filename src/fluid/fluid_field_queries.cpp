// What the fluid solver tells of its state: global copies of its vectors, the forces on
// the walls, the whole velocity with its subscale part, the velocity's integrals (mean
// velocity, kinetic energy), and the velocity and pressure at the mesh's nodes
// (fluid/fluid_solver.hpp).
#include "fluid/fluid_solver.hpp"

#include <KokkosBlas1_axpby.hpp>
#include <algorithm>

#include "fluid/fluid_element_types.hpp"
#include "util/view_transfer.hpp"

namespace rouleau {

void FluidSolver::gather_global(const ConstVector& local, const Vector& global,
                                const Kokkos::View<const int*>& nodes) const {
  exchange_->replicate(local, global, nodes);
}

std::vector<double> FluidSolver::global_values(const ConstVector& local) const {
  if (!exchange_->spans_ranks()) return to_flat_vector(local);
  Vector global("rouleau::FluidSolver::global_values", num_global_unknowns_);
  exchange_->replicate(local, global);
  return to_flat_vector(global);
}

std::vector<std::array<double, 3>> FluidSolver::boundary_forces(const std::vector<std::string>& sides,
                                                                const ImmersedTerms& immersed) {
  const FluidMesh& mesh = mesh_;
  // One residual without constraint rows and one host copy for all the sides asked.
  load_immersed_forces(immersed);
  residual_at_state(immersed, false);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), residual_);
  std::vector<std::array<double, 3>> forces;
  for (const std::string& side : sides) {
    std::vector<int> dof_nodes;
    for (int node : mesh.boundary(side).nodes) dof_nodes.push_back(mesh.dof_node_of_node[node]);
    std::sort(dof_nodes.begin(), dof_nodes.end());
    dof_nodes.erase(std::unique(dof_nodes.begin(), dof_nodes.end()), dof_nodes.end());
    // R_a = ∫ ∇N_a : σ − ... = the force the wall exerts on the fluid at node a; the fluid
    // pushes back with −R_a. Scaled force → pN: × P L².
    // Across ranks each node is counted by its owner (its residual is whole there).
    std::array<double, 3> force{0.0, 0.0, 0.0};
    for (int global_node : dof_nodes) {
      const int n = exchange_->local_node(global_node);
      if (n < 0 || n >= exchange_->num_owned_nodes()) continue;
      for (int d = 0; d < 3; ++d) force[d] -= r(4 * n + d) * scales_.force();
    }
    exchange_->sum(force.data(), 3);
    forces.push_back(force);
  }
  return forces;
}

void FluidSolver::total_velocity(const Vector& out, const ImmersedTerms& immersed) {
  load_immersed_forces(immersed);
  operator_.subscale_velocity(state_, out, immersed.subscale_region);
  KokkosBlas::axpy(1.0, state_, out);
}

namespace {
using ExecSpace = Kokkos::DefaultExecutionSpace;

// ∫ 1, ∫ u_x, ∫ u_y, ∫ u_z, ∫ |u|² over the mesh (scaled), by the element's quadrature
// with u(ξ_q) = Σ_a N_a(ξ_q) u_a.
template <class Element>
std::array<double, 5> integrate_velocity(const FluidOperator& op, const ConstVector& state) {
  const auto geometry = op.geometry();
  const auto dof_nodes = op.mesh().element_dof_nodes;
  double v = 0.0, ux = 0.0, uy = 0.0, uz = 0.0, uu = 0.0;
  Kokkos::parallel_reduce(
      "rouleau::FluidSolver::velocity_integrals", Kokkos::RangePolicy<ExecSpace>(0, op.mesh().num_elements),
      KOKKOS_LAMBDA(const int e, double& volume, double& mx, double& my, double& mz, double& squared) {
        for (int q = 0; q < Element::quadrature_points; ++q) {
          double xi[3];
          Element::quadrature_point(q, xi);
          const double dv = geometry(e, q, 9);
          double u[3] = {0.0, 0.0, 0.0};
          for (int a = 0; a < Element::nodes; ++a) {
            const double N = Element::shape(a, xi);
            const int n = dof_nodes(e, a);
            for (int c = 0; c < 3; ++c) u[c] += N * state(4 * n + c);
          }
          volume += dv;
          mx += dv * u[0];
          my += dv * u[1];
          mz += dv * u[2];
          squared += dv * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        }
      },
      v, ux, uy, uz, uu);
  return {v, ux, uy, uz, uu};
}
}  // namespace

std::array<double, 5> FluidSolver::velocity_integrals() const {
  // Across ranks: each rank integrates over the elements it owns.
  std::array<double, 5> integrals = visit_fluid_element(operator_.mesh().element_type, [&](auto element) {
    return integrate_velocity<decltype(element)>(operator_, state_);
  });
  exchange_->sum(integrals.data(), 5);
  return integrals;
}

std::array<double, 3> FluidSolver::mean_velocity() const {
  const auto integrals = velocity_integrals();
  const double U = scales_.velocity;
  return {integrals[1] / integrals[0] * U, integrals[2] / integrals[0] * U, integrals[3] / integrals[0] * U};
}

double FluidSolver::kinetic_energy() const {
  // ½ ρ ∫ |u|² dV, the integral in scaled (x/L, u/U) variables: × U² L³
  const double U = scales_.velocity, L = scales_.length;
  return 0.5 * density_ * velocity_integrals()[4] * U * U * L * L * L;
}

void FluidSolver::velocity_and_pressure(std::vector<double>& velocity, std::vector<double>& pressure) const {
  const std::vector<double> host = global_values(state_);
  const FluidMesh& mesh = mesh_;
  velocity.resize(3 * mesh.num_nodes);
  pressure.resize(mesh.num_nodes);
  for (int n = 0; n < mesh.num_nodes; ++n) {
    const int d = mesh.dof_node_of_node[n];
    for (int c = 0; c < 3; ++c) velocity[3 * n + c] = host[4 * d + c] * scales_.velocity;
    pressure[n] = host[4 * d + 3] * scales_.pressure;
  }
}

}  // namespace rouleau
