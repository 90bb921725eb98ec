#pragma once
// XDMF 3 + HDF5 time series of unstructured meshes (8-node hexahedra, 4-node tetrahedra),
// for ParaView (docs/paraview.md says which reader to pick).
//
// Files in DIRECTORY:
//   BASENAME_mesh.h5     written once: /MESH/coordinates (n_nodes x 3, float64),
//                        /MESH/connectivity (n_cells x nodes_per_cell, int64), per mesh
//   BASENAME_NNNNNN.h5   one per step: /step (int64), /time (float64), and per mesh
//                        /MESH/FIELD (n, or n x 3 for vectors, float64) and, for a moving
//                        mesh, /MESH/coordinates (n_nodes x 3)
//   BASENAME_MESH.xdmf   one per mesh: a temporal collection of that mesh alone, one
//                        uniform grid named MESH per step. Every reader (ParaView 5.11's "XDMF
//                        Reader", "Xdmf3ReaderS", "Xdmf3ReaderT") opens it as one dataset
//                        that plays through the steps.
//   BASENAME.xdmf        every mesh in one file. With one mesh: a temporal collection of
//                        uniform grids, as above. With several: a spatial collection holding
//                        one temporal collection per mesh, named MESH, each with one uniform
//                        grid named MESH per step. ParaView's "XDMF Reader" shows one block
//                        per mesh, named MESH at every step; "Xdmf3ReaderT" the same blocks
//                        at every step, unnamed; "Xdmf3ReaderS" merges the meshes into one.
//                        Not a temporal collection of per-step spatial collections: the
//                        readers make repeated grid names unique (MESH, MESH[1], MESH[2], ...),
//                        so a mesh's block would change its name from step to step.
//   Before the first step the .xdmf files hold the bare meshes (no time, no fields); the
//   .xdmf files are rewritten after every step and list the steps written so far.
// Every file is written to PATH.tmp and renamed once complete (io/atomic_file.hpp), and the
// .xdmf files are rewritten only after the step's .h5 is in place: an interrupted run leaves
// only complete files, and an .xdmf refers only to files that exist. Every .h5 carries the
// provenance (plus "mesh_hash_MESH" for each mesh) as string attributes of its root group;
// every .xdmf carries it as <Information Name=KEY Value=VALUE/> elements of its Domain.
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
  // static geometry and topology, and the .xdmf files of the bare meshes (replacing stale
  // ones; ParaView's readers crash on an empty temporal collection, so the collections start
  // with the first step).
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
  // (NNNNNN = step, 6 digits at least), then rewrites the .xdmf files to include it. Throws
  // like the constructor; on a throw the .xdmf files still describe the earlier steps (or,
  // when rewriting an .xdmf itself failed, some of them this step too, whose .h5 is in place).
  void write_step(int step, double time, const std::vector<std::vector<FieldView>>& nodal_fields_per_mesh,
                  const std::vector<std::vector<FieldView>>& cell_fields_per_mesh,
                  const std::vector<const double*>& moved_coordinates_per_mesh = {});

  // Continuing a series after a restart: lists again the step files already in the
  // directory up to `last_step` (each read back for its time and its fields), deletes those
  // of later steps (written after the checkpoint the run continues from), and rewrites the
  // .xdmf files. Call it once, before write_step. Throws std::runtime_error naming a step file
  // that cannot be read.
  void adopt_written_steps(int last_step);

  // DIRECTORY/BASENAME.xdmf: every mesh in one file.
  std::string xdmf_path() const;
  // DIRECTORY/BASENAME_MESH.xdmf: mesh `mesh_name` alone.
  std::string mesh_xdmf_path(const std::string& mesh_name) const;
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
  // The text of BASENAME.xdmf (every mesh), or of BASENAME_MESH.xdmf when `only_mesh` is a
  // mesh index.
  static constexpr std::size_t all_meshes = static_cast<std::size_t>(-1);
  std::string xdmf_text(std::size_t only_mesh = all_meshes) const;
  // Rewrites every .xdmf file: the per-mesh files, then BASENAME.xdmf.
  void write_xdmf_files() const;
  // One mesh's time series: a temporal collection named `name` of its uniform grids, one per
  // step, or the static mesh alone before the first step.
  void append_mesh_series(std::string& xml, std::size_t mesh_index, const std::string& name,
                          const std::string& indent) const;
  // One mesh's uniform <Grid>: at `step` (with its Time and its fields), or the static mesh
  // alone when `step` is null.
  void append_uniform_grid(std::string& xml, std::size_t mesh_index, const StepRecord* step,
                           const std::string& indent) const;

  std::string directory_;
  std::string basename_;
  std::vector<MeshLayout> meshes_;
  Provenance provenance_;
  std::vector<StepRecord> steps_;
};

}  // namespace rouleau
