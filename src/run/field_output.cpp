// The run's field output: the meshes described for the XDMF writer, and one step of
// fields per call (run/field_output.hpp).
#include "run/field_output.hpp"

namespace rouleau {

namespace {
// The fluid mesh as the XDMF writer wants it (host arrays).
MeshDescription describe_fluid_mesh(const FluidMesh& mesh) {
  MeshDescription d;
  d.name = "fluid";
  d.cell_type = mesh.element_type == FluidElementType::hexahedron8 ? CellType::hexahedron8 : CellType::tetrahedron4;
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto c = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_nodes);
  d.coordinates.resize(3 * mesh.num_nodes);
  for (int n = 0; n < mesh.num_nodes; ++n)
    for (int k = 0; k < 3; ++k) d.coordinates[3 * n + k] = x(n, k);
  d.connectivity.resize(static_cast<size_t>(mesh.num_elements) * mesh.nodes_per_element);
  for (int e = 0; e < mesh.num_elements; ++e)
    for (int a = 0; a < mesh.nodes_per_element; ++a) d.connectivity[e * mesh.nodes_per_element + a] = c(e, a);
  return d;
}
}  // namespace

std::vector<MeshDescription> output_meshes(const Simulation& simulation) {
  std::vector<MeshDescription> meshes{describe_fluid_mesh(simulation.mesh())};
  if (simulation.cells().population) meshes.push_back(simulation.cells().population->mesh_description());
  return meshes;
}

FieldOutput::FieldOutput(const Simulation& simulation, const Communicator& ranks, std::vector<MeshDescription> meshes,
                         const Provenance& provenance, const std::string& output_dir, const FoundCheckpoint* restart,
                         const bool writes_files)
    : ranks_(ranks), write_fields_(simulation.config().output.write_fields) {
  for (const MeshDescription& mesh : meshes) mesh_names_.push_back(mesh.name);
  if (write_fields_ && writes_files) {
    series_ = std::make_unique<XdmfTimeSeries>(output_dir, "fields", std::move(meshes), provenance);
    if (restart) series_->adopt_written_steps(static_cast<int>(restart->data.step));
  }
  const CaseCells& cells = simulation.cells();
  if (cells.interaction)
    host_interaction_forces_ = decltype(host_interaction_forces_)("rouleau::run::interaction_forces_host",
                                                                  cells.population->num_nodes());
}

void FieldOutput::write(Simulation& simulation) {
  if (!write_fields_) return;
  simulation.times().time("output", [&] {
    simulation.fluid().velocity_and_pressure(velocity_, pressure_);
    std::vector<std::vector<FieldView>> nodal{
        {FieldView{"velocity_um_s", 3, velocity_.data()}, FieldView{"pressure_Pa", 1, pressure_.data()}}};
    std::vector<const double*> moved{nullptr};
    const CaseCells& cells = simulation.cells();
    if (cells.population) {
      // The forces the step computed at these positions (internal_force is CellForces' elastic).
      const CellForceState& forces = simulation.cell_forces(false);
      cells.population->copy_fields_to_host(cell_fields_);
      // Each rank's share of the cells' forces: the fields are their sums.
      const bool shared = cells.population->work_is_shared();
      if (shared) ranks_.sum(cell_fields_.internal_force.data(), static_cast<int>(cell_fields_.internal_force.size()));
      nodal.push_back({FieldView{"displacement_um", 3, cell_fields_.displacement.data()},
                       FieldView{"velocity_um_s", 3, cell_fields_.velocity.data()},
                       FieldView{"internal_force_pN", 3, cell_fields_.internal_force.data()},
                       FieldView{"cell_id", 1, cell_fields_.cell_id.data()}});
      if (cells.interaction) {
        Kokkos::deep_copy(host_interaction_forces_, forces.interaction);
        if (shared) ranks_.sum(host_interaction_forces_.data(), static_cast<int>(host_interaction_forces_.size()));
        nodal.back().push_back(FieldView{"interaction_force_pN", 3, host_interaction_forces_.data()});
      }
      moved.push_back(cell_fields_.positions.data());
    }
    if (series_) series_->write_step(simulation.steps(), simulation.time(), nodal, {}, moved);
  });
}

std::vector<std::string> FieldOutput::mesh_xdmf_paths() const {
  std::vector<std::string> paths;
  if (series_)
    for (const std::string& name : mesh_names_) paths.push_back(series_->mesh_xdmf_path(name));
  return paths;
}

}  // namespace rouleau
