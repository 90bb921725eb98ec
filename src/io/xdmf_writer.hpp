#pragma once
// XDMF 3 + HDF5 time series of unstructured meshes (8-node hexahedra, 4-node tetrahedra),
// readable by ParaView ("XDMF Reader" / "Xdmf3 Reader").
//
// Files in DIRECTORY:
//   BASENAME_mesh.h5     written once: /MESH/coordinates (n_nodes x 3, float64),
//                        /MESH/connectivity (n_cells x nodes_per_cell, int64), per mesh
//   BASENAME_NNNNNN.h5   one per step: /step (int64), /time (float64), and per mesh
//                        /MESH/FIELD (n, or n x 3 for vectors, float64) and, for a moving
//                        mesh, /MESH/coordinates (n_nodes x 3)
//   BASENAME.xdmf        a temporal collection of the steps written so far, rewritten after
//                        every step; with several meshes each step is a spatial collection
// Every file is written to PATH.tmp and renamed once complete (io/atomic_file.hpp), and the
// .xdmf is rewritten only after the step's .h5 is in place: an interrupted run leaves only
// complete files, and the .xdmf refers only to files that exist. Every .h5 carries the
// provenance (plus "mesh_hash_MESH" for each mesh) as string attributes of its root group;
// the .xdmf carries it as <Information Name=KEY Value=VALUE/> elements of its Domain.
//
// Host-only: includes no Kokkos header. Fields arrive as plain host pointers: copy device
// Views to the host first, and note that data must be entity-major (LayoutRight: x0 y0 z0
// x1 ...), so a LayoutLeft View<double*[3]> (CUDA's default) needs a LayoutRight copy.
#include <cstddef>
#include <string>
#include <vector>

#include "io/provenance.hpp"

namespace rouleau {

// Cell shapes. Node order is VTK's (= XDMF's): hexahedron nodes 0-3 counter-clockwise on
// the bottom face, 4-7 above them; tetrahedron nodes 0-2 counter-clockwise seen from node 3.
enum class CellType { hexahedron8, tetrahedron4 };

// Nodes per cell of `cell_type` (8 or 4).
int nodes_per_cell(CellType cell_type);

// An unstructured mesh to be written. Names (mesh, field, basename) use only letters, digits,
// '_', '-' and '.': they become HDF5 paths, file names and XML attribute values.
struct MeshDescription {
  std::string name;                   // e.g. "fluid", "cells"; unique within a series
  CellType cell_type;
  std::vector<double> coordinates;    // n_nodes x 3, node-major
  std::vector<long long> connectivity;  // n_cells x nodes_per_cell, 0-based node indices
};

// One field of one mesh at one step, borrowed for the duration of write_step.
struct FieldView {
  std::string name;     // unique among the mesh's node and cell fields; not "coordinates"
  int components;       // 1 (XDMF "Scalar") or 3 ("Vector")
  const double* data;   // n_nodes (or n_cells) x components, node- (cell-) major
};

class XdmfTimeSeries {
 public:
  // Creates `directory` if missing, writes DIRECTORY/BASENAME_mesh.h5 with every mesh's
  // static geometry and topology, and an .xdmf of the bare meshes (replacing a stale one;
  // ParaView's readers crash on an empty temporal collection, so it starts with the first step).
  // Throws std::invalid_argument for a bad name, an empty mesh, an array size that is not a
  // multiple of 3 (nodes_per_cell), or a node index out of range; std::runtime_error naming
  // the file and dataset when HDF5 fails.
  XdmfTimeSeries(std::string directory, std::string basename, std::vector<MeshDescription> meshes,
                 Provenance provenance);

  // Writes step `step` (greater than every step written before) at `time`:
  // nodal_fields_per_mesh[m] and cell_fields_per_mesh[m] are the fields of mesh m (each
  // outer vector either empty = no such fields, or one entry per mesh);
  // moved_coordinates_per_mesh[m] is either nullptr (mesh m does not move) or n_nodes x 3
  // current positions (the outer vector empty = no mesh moves). Writes BASENAME_NNNNNN.h5
  // (NNNNNN = step, 6 digits at least), then rewrites BASENAME.xdmf to include it. Throws
  // like the constructor; on a throw the .xdmf still describes the earlier steps.
  void write_step(int step, double time, const std::vector<std::vector<FieldView>>& nodal_fields_per_mesh,
                  const std::vector<std::vector<FieldView>>& cell_fields_per_mesh,
                  const std::vector<const double*>& moved_coordinates_per_mesh = {});

  // Continuing a series after a restart: lists again the step files already in the
  // directory up to `last_step` (each read back for its time and its fields), deletes those
  // of later steps (written after the checkpoint the run continues from), and rewrites the
  // .xdmf. Call it once, before write_step. Throws std::runtime_error naming a step file
  // that cannot be read.
  void adopt_written_steps(int last_step);

  // DIRECTORY/BASENAME.xdmf: the file to open in ParaView.
  std::string xdmf_path() const;
  // DIRECTORY/BASENAME_mesh.h5: the static geometry and topology.
  std::string mesh_path() const;
  // DIRECTORY/BASENAME_NNNNNN.h5: the fields of step `step`.
  std::string step_path(int step) const;
  // Number of steps written (listed in the .xdmf).
  std::size_t step_count() const { return steps_.size(); }

 private:
  // What the .xdmf needs to know of a mesh once its arrays are on disk.
  struct MeshLayout {
    std::string name;
    CellType cell_type;
    std::size_t node_count;
    std::size_t cell_count;
  };
  enum class Center { node, cell };
  struct FieldRecord {
    std::string name;
    Center center;
    int components;
  };
  struct MeshStepRecord {
    bool moved;
    std::vector<FieldRecord> fields;
  };
  struct StepRecord {
    int step;
    double time;
    std::vector<MeshStepRecord> meshes;
  };

  std::string file_name_of_step(int step) const;
  std::string xdmf_text() const;
  // One mesh's <Grid>: at `step` (with its Time when there is one mesh, and its fields), or
  // the static mesh alone when `step` is null.
  void append_uniform_grid(std::string& xml, std::size_t mesh_index, const StepRecord* step,
                           const std::string& indent) const;

  std::string directory_;
  std::string basename_;
  std::vector<MeshLayout> meshes_;
  Provenance provenance_;
  std::vector<StepRecord> steps_;
};

}  // namespace rouleau
