#pragma once
// The run's fields (output.write_fields): one step of the XDMF time series
// DIRECTORY/fields*.xdmf (io/xdmf_writer.hpp) per call, with the fluid's velocity and
// pressure at its nodes and, with cells, their displacement, velocity, internal and
// interaction forces, cell id and current positions. Every rank takes part (the fluid's
// fields are gathered, the cells' forces summed over the ranks that share them); the first
// rank writes the files.
#include <memory>
#include <string>
#include <vector>

#include <Kokkos_Core.hpp>

#include "io/checkpoint_file.hpp"
#include "io/provenance.hpp"
#include "io/xdmf_writer.hpp"
#include "parallel/communicator.hpp"
#include "run/simulation.hpp"

namespace rouleau {

// The meshes of the output as the XDMF writer wants them (host arrays): the fluid's, then
// the cells' as they are now (with cells).
std::vector<MeshDescription> output_meshes(const Simulation& simulation);

class FieldOutput {
 public:
  // `meshes`: output_meshes() of the simulation as built (before a restart moves the
  // cells). When the case writes fields, the first rank (`writes_files`) starts the series
  // in `output_dir` with `provenance`; after a `restart` it continues the series after the
  // checkpoint's step, dropping later steps. `ranks` must outlive it.
  FieldOutput(const Simulation& simulation, const Communicator& ranks, std::vector<MeshDescription> meshes,
              const Provenance& provenance, const std::string& output_dir, const FoundCheckpoint* restart,
              bool writes_files);

  // The fields of the simulation's current step (timed as the stage "output"); nothing when
  // the case writes no fields.
  void write(Simulation& simulation);

  // The .xdmf file of each mesh (to open in ParaView), or none when this rank writes no
  // fields.
  std::vector<std::string> mesh_xdmf_paths() const;

 private:
  const Communicator& ranks_;
  bool write_fields_;
  std::vector<std::string> mesh_names_;
  std::unique_ptr<XdmfTimeSeries> series_;  // the first rank's, with fields
  // Host copies of the step's fields, kept from call to call.
  std::vector<double> velocity_, pressure_;
  CellPopulation::HostFields cell_fields_;
  // The interaction forces per cell node (a node-major host copy).
  Kokkos::View<double* [3], Kokkos::LayoutRight, Kokkos::HostSpace> host_interaction_forces_;
};

}  // namespace rouleau
