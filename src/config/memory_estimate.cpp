#include "config/memory_estimate.hpp"

#include "config/derived.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "geometry/cell_mesh.hpp"
#include "geometry/vessel_mesh.hpp"
#include "util/errors.hpp"

namespace rouleau {
namespace {

constexpr double kib = 1024.0;
constexpr double largest_int = 2147483647.0;  // 2^31 − 1

// The fluid mesh's sizes, as src/mesh builds it.
struct FluidSizes {
  double nodes = 0.0;           // N: nodes with unknowns
  double geometric_nodes = 0.0; // N_g: every node, a periodic pair twice
  double elements = 0.0;        // E
  double nodes_per_element = 8.0;
  double quadrature_points = 8.0;
  double blocks_per_node = 27.0;  // B: 4x4 blocks per row of the Jacobian's block graph
  double widest_ilu_level = 1.0;  // rows in the widest level of ILU(0)'s level schedule
  bool uniform_box = false;       // the uniform box's stencil is stored (uniform_box_stencil.cpp)
};

// A box of hexahedra (mesh/box_mesh.cpp): D_d = n_d node planes along a periodic direction,
// n_d + 1 otherwise. Each node couples to the nodes of its 8 elements: 3 planes per
// direction inside, 2 on a non-periodic boundary, so the block graph has Π_d(3 D_d − 2)
// blocks (Π_d 3 D_d when periodic). ILU(0)'s level schedule on the lexicographic order
// (x fastest) orders the nodes (i, j, k) of a box closed in x and y by i + 2j + 4k, and a
// node's 4 unknowns fall on 4 different levels: the widest level holds as many rows as the
// largest count of nodes with the same i + 2j + 4k (tests/test_memory_estimate.cpp checks
// it against the factorization). A periodic x or y links each
// line's ends, and the levels then follow z alone: about D_z / 2 + 1 nodes wide.
FluidSizes box_sizes(const DomainConfig& domain) {
  FluidSizes sizes;
  double planes[3], blocks = 1.0;
  bool periodic[3];
  for (int d = 0; d < 3; ++d) {
    periodic[d] = domain.boundary[2 * d].type == BoundaryType::periodic;
    const double n = domain.elements[d];
    planes[d] = periodic[d] ? n : n + 1.0;
    blocks *= periodic[d] ? 3.0 * planes[d] : 3.0 * planes[d] - 2.0;
  }
  sizes.nodes = planes[0] * planes[1] * planes[2];
  sizes.geometric_nodes = (domain.elements[0] + 1.0) * (domain.elements[1] + 1.0) * (domain.elements[2] + 1.0);
  sizes.elements = double(domain.elements[0]) * domain.elements[1] * domain.elements[2];
  sizes.blocks_per_node = blocks / sizes.nodes;
  sizes.uniform_box = domain.wall_grading[0] == 1.0 && domain.wall_grading[1] == 1.0 && domain.wall_grading[2] == 1.0;
  if (periodic[0] || periodic[1]) {
    sizes.widest_ilu_level = planes[2] / 2.0 + 1.0;
  } else if (sizes.nodes < 1e9) {
    // count(c) = #{(i, j, k): i + 2j + 4k = c}, from the count of i + 2j = s.
    const long long nx = static_cast<long long>(planes[0]), ny = static_cast<long long>(planes[1]),
                    nz = static_cast<long long>(planes[2]);
    std::vector<double> in_plane(nx + 2 * ny, 0.0);
    for (long long j = 0; j < ny; ++j)
      for (long long i = 0; i < nx; ++i) in_plane[i + 2 * j] += 1.0;
    double widest = 0.0;
    for (long long c = 0; c < nx + 2 * ny + 4 * nz; ++c) {
      double count = 0.0;
      for (long long k = 0; k < nz && 4 * k <= c; ++k)
        if (c - 4 * k < static_cast<long long>(in_plane.size())) count += in_plane[c - 4 * k];
      widest = std::max(widest, count);
    }
    sizes.widest_ilu_level = widest;
  } else {
    sizes.widest_ilu_level = planes[0] * planes[1] / 8.0;  // the same count's order, not its value
  }
  return sizes;
}

// A vessel of tetrahedra (geometry/vessel_mesh.cpp, Gmsh), sized from the mesher's size
// field (expected_element_count, the count the mesher's own limit uses). Measured on the
// contraction at 3/1.5, 2/1 and 1.5/0.75 μm (tests/test_vessel_mesh.cpp): Gmsh makes
// 1.58-1.69 times that count, 4.2-5.1 tetrahedra per node, 12.6-13.4 blocks per row, and
// its node order along the axis gives ILU(0) narrow levels, 17 and 25 rows at 3.7k and 10k
// nodes (about 1.1 N^(1/3)).
FluidSizes vessel_sizes(const VesselConfig& vessel) {
  FluidSizes sizes;
  sizes.nodes_per_element = 4.0;
  sizes.quadrature_points = 4.0;
  sizes.elements = 1.6 * expected_element_count(vessel.profile, vessel.sizes);
  sizes.nodes = sizes.elements / 4.6;
  sizes.geometric_nodes = sizes.nodes;
  sizes.blocks_per_node = 13.0;
  sizes.widest_ilu_level = 1.1 * std::cbrt(sizes.nodes);
  return sizes;
}

// Nodes of a cell mesh of `kind` (geometry/cell_mesh.cpp: about the same count for any cell
// size at a preset; a mesh_size_um override scales it with the element size cubed).
double cell_mesh_nodes(const CellKindConfig& kind) {
  const bool shell = kind.body == CellBody::shell;
  double preset = 0.0;
  switch (kind.resolution) {
    case MeshResolution::coarse: preset = shell ? 346 : 210; break;
    case MeshResolution::paper: preset = shell ? 1238 : 1039; break;
    case MeshResolution::fine: preset = shell ? 4831 : 5983; break;
  }
  if (kind.mesh_size <= 0.0) return preset;
  CellKindConfig at_preset = kind;
  at_preset.mesh_size = 0.0;
  const double ratio = cell_element_size(at_preset) / kind.mesh_size;
  return preset * ratio * ratio * (shell ? 1.0 : ratio);
}

}  // namespace

MemoryEstimate estimate_memory(const CaseConfig& config, int threads) {
  const FluidSizes f = config.vessel.enabled ? vessel_sizes(config.vessel) : box_sizes(config.domain);
  const double N = f.nodes, Ng = f.geometric_nodes, E = f.elements, B = f.blocks_per_node;
  const double T = std::max(1, threads), m = config.solver.gmres_restart;
  MemoryEstimate estimate;
  estimate.fluid_nodes = static_cast<long long>(N);
  estimate.fluid_elements = static_cast<long long>(E);
  estimate.jacobian_blocks = B * N;
  estimate.widest_ilu_level = f.widest_ilu_level;
  auto add = [&estimate](const std::string& what, double bytes) {
    if (bytes > 0.0) estimate.terms.emplace_back(what, bytes);
  };

  // The process itself: libraries, Kokkos, HDF5, Gmsh.
  add("program and libraries", 60.0 * kib * kib);
  // mesh/box_mesh.cpp, vessel_fluid_mesh.cpp: coordinates, two connectivities, the
  // node-to-unknown map in three copies (the simulation, the solver, the operator).
  add("fluid mesh", 24.0 * Ng + 8.0 * f.nodes_per_element * E + 12.0 * Ng);
  // fluid/fluid_operator.cpp: 10 doubles per quadrature point (shape gradients, weight),
  // element sizes, lumped mass, colours.
  add("element geometry", 80.0 * f.quadrature_points * E + 12.0 * E + 8.0 * N);
  // fluid_solver.cpp, fluid_operator.cpp, boundary_conditions.cpp: 7 state vectors (8 in
  // the Stokes limit: R(0) is kept), the projected gradients (9 per node, three), traction
  // loads, and per thread the scattered sums of gradients and residuals (Kokkos ScatterView
  // copies on CPU threads).
  add("fluid state and sums", (536.0 + (f.uniform_box ? 72.0 : 0.0)) * N + 104.0 * T * N);
  // solver/gmres.cpp: the Krylov basis, at most m + 1 vectors of 4N (it grows with the
  // iterations the solves need), and 3 work vectors.
  add("GMRES(" + std::to_string(config.solver.gmres_restart) + ") basis", 32.0 * (m + 1.0) * N + 96.0 * N);
  // fluid/fluid_starting_guess.cpp: a Stokes run in time keeps its last k solutions and,
  // as scratch, k combinations of them and their images (3k vectors of 4N).
  const int k = config.solver.starting_guess_solutions;
  if (k > 0 && config.time.mode == TimeMode::transient && derive_quantities(config).stokes)
    add("starting guess: last " + std::to_string(k) + " solutions", 96.0 * k * N);
  // fluid/fluid_matrix.cpp and the preconditioners (solver/).
  const double ilu_scratch = 16.0 * f.widest_ilu_level * N;  // KokkosKernels' spiluk numeric: rows x widest level ints
  const PreconditionerType preconditioner = derive_quantities(config).preconditioner;
  switch (preconditioner) {
    case PreconditionerType::none: break;
    case PreconditionerType::block_jacobi: add("block-Jacobi blocks", (256.0 + 128.0 * T) * N); break;
    case PreconditionerType::fast_diagonalization: {
      // fluid/fast_diagonalization.cpp: per pair of wave numbers, N_first (N_last/2 + 1) of
      // them (the real transform halves the last periodic axis), a banded LU of 4 unknowns
      // per wall plane: 34 complex bands (16 B), a pivot and a spectrum entry per unknown;
      // while factoring, a probe and its response.
      int wall = 0;
      while (wall < 2 && config.domain.boundary[2 * wall].type == BoundaryType::periodic) ++wall;
      const int first = wall == 0 ? 1 : 0, last = wall == 2 ? 1 : 2;
      const double unknowns_per_wave = 4.0 * (config.domain.elements[wall] + 1.0);
      const double waves = config.domain.elements[first] * (config.domain.elements[last] / 2 + 1.0);
      add("fast diagonalization: banded factors per wave number", waves * unknowns_per_wave * (34.0 * 16.0 + 20.0) +
                                                                      64.0 * N);
      break;
    }
    case PreconditionerType::ilu0:
      // the Jacobian's block graph and values, the ILU(0) factors and their schedule
      add("ILU(0): Jacobian blocks and factors", (228.0 + 388.0 * B) * N + 4.0 * E);
      add("ILU(0) level-schedule scratch", ilu_scratch);
      break;
    case PreconditionerType::automatic:  // never: derive_quantities resolves it
    case PreconditionerType::multigrid:
      // Aggregates of up to 4 nodes: the coarse levels hold 0.30–0.32 of the fine level's
      // blocks (measured on hexahedra and tetrahedra, 16³–32³). Per level of N_l nodes with
      // B_l blocks each: values, columns, block rows and contributions (204 B_l N_l bytes),
      // row map and vectors; block-Jacobi keeps 2 × 16 doubles and 2 vectors (a sweep's buffer and the
      // power iteration's) per node, and in single precision a float copy of every level's
      // values but the coarsest's (64 B_l N_l bytes, 1.31 times the fine level's); ILU(0) its factors.
      if (config.solver.multigrid_smoother == MultigridSmoother::block_jacobi) {
        const double rounded = config.solver.multigrid_precision == MultigridPrecision::single_precision ? 84.0 : 0.0;
        add("multigrid: Jacobian blocks, block-Jacobi smoothers, coarse levels",
            (595.0 + (270.0 + rounded) * B) * N + 4.0 * E);
      } else {
        add("multigrid: Jacobian blocks, ILU(0) smoothers, coarse levels", (380.0 + 520.0 * B) * N + 4.0 * E);
        add("ILU(0) level-schedule scratch", ilu_scratch);
      }
      add("multigrid set-up (aggregation graphs)", 1.7 * kib * N);
      break;
  }
  // run/field_output.cpp, io/xdmf_writer.cpp: the host description of the fluid mesh, and with
  // fields a second one in the writer and the velocity and pressure gathered for output.
  add("output", 24.0 * Ng + 8.0 * f.nodes_per_element * E +
                    (config.output.write_fields ? 24.0 * Ng + 8.0 * f.nodes_per_element * E + 32.0 * Ng : 0.0));

  // Cells: their meshes, states and forces (cells/), RKPM rows of about 64 fluid nodes per
  // cell node (coupling/rkpm_coupler.cpp), the coupling's vectors on both meshes.
  double cell_nodes = 0.0;
  for (const CellPlacement& cell : config.cells)
    for (const CellKindConfig& kind : config.cell_kinds)
      if (kind.name == cell.kind) cell_nodes += cell_mesh_nodes(kind);
  estimate.cell_nodes = static_cast<long long>(cell_nodes);
  const bool semi_implicit = config.coupling.scheme == CouplingScheme::semi_implicit;
  if (cell_nodes > 0.0) {
    add("cells and their coupling", cell_nodes * (3.2 * kib + 24.0 * T) + N * (212.0 + 32.0 * T + (semi_implicit ? 64.0 : 0.0)));
    // cells/surface_interaction.cpp: neighbour lists of an aggregate's density (about 360
    // entries per surface point), and for the semi-implicit step its pairs in range.
    if (config.interaction.enabled) add("Morse neighbour lists", cell_nodes * (6.0 + (semi_implicit ? 20.0 : 0.0)) * kib);
  }

  std::sort(estimate.terms.begin(), estimate.terms.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  for (const auto& [what, bytes] : estimate.terms) estimate.total_bytes += bytes;

  // 32-bit counts: the Jacobian's blocks (ILU(0), multigrid), block-Jacobi's 16 per node, the
  // 9 projected gradients per node, the output's connectivity and coordinates.
  std::vector<std::pair<double, std::string>> counts{{9.0 * N, "projected-gradient entries (9 per node)"},
                                                     {f.nodes_per_element * E, "element-node entries"},
                                                     {3.0 * Ng, "node coordinates"}};
  if (preconditioner == PreconditionerType::ilu0 || preconditioner == PreconditionerType::multigrid)
    counts.emplace_back(B * N, "4x4 blocks of the preconditioner's matrix");
  if (preconditioner == PreconditionerType::block_jacobi)
    counts.emplace_back(16.0 * N, "block-Jacobi entries (16 per node)");
  const auto largest = *std::max_element(counts.begin(), counts.end());
  estimate.largest_index_count = largest.first;
  estimate.largest_index_what = largest.second;
  return estimate;
}

double available_memory_bytes() {
  double available = -1.0;
  std::ifstream meminfo("/proc/meminfo");
  std::string name;
  double kilobytes = 0.0;
  std::string unit;
  while (meminfo >> name >> kilobytes >> unit)
    if (name == "MemAvailable:") available = kilobytes * 1024.0;
  // A cgroup v2 limit (a container, a batch job's): what is left of the tightest one from
  // this process's group up to the root.
  std::ifstream groups("/proc/self/cgroup");
  std::string line, group;
  while (std::getline(groups, line))
    if (line.rfind("0::", 0) == 0) group = line.substr(3);
  for (std::filesystem::path folder = "/sys/fs/cgroup" + group;; folder = folder.parent_path()) {
    std::ifstream limit_file(folder / "memory.max"), current_file(folder / "memory.current");
    double limit = 0.0, current = 0.0;
    if (limit_file >> limit && current_file >> current) {  // "max" (no limit) reads as no number
      const double left = std::max(0.0, limit - current);
      available = available < 0.0 ? left : std::min(available, left);
    }
    if (folder == "/sys/fs/cgroup" || folder == folder.parent_path()) break;
  }
  return available;
}

std::string format_bytes(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6) {
    bytes /= 1024.0;
    ++unit;
  }
  char text[32];
  // three significant digits
  const char* format = unit == 0 || bytes >= 100.0 ? "%.0f %s" : bytes >= 10.0 ? "%.1f %s" : "%.2f %s";
  std::snprintf(text, sizeof text, format, bytes, units[unit]);
  return text;
}

std::string describe_memory(const MemoryEstimate& estimate, double available_bytes) {
  std::ostringstream text;
  text << "memory    about " << format_bytes(estimate.total_bytes) << " ("
       << (available_bytes >= 0.0 ? format_bytes(available_bytes) + " available" : std::string("available unknown"))
       << "): " << estimate.fluid_nodes << " fluid nodes, " << estimate.fluid_elements << " elements"
       << (estimate.cell_nodes > 0 ? ", " + std::to_string(estimate.cell_nodes) + " cell nodes" : std::string()) << "\n";
  for (std::size_t i = 0; i < estimate.terms.size() && i < 4; ++i)
    text << "          " << format_bytes(estimate.terms[i].second) << "  " << estimate.terms[i].first << "\n";
  return text.str();
}

void require_memory(const CaseConfig& config, const MemoryEstimate& estimate, double available_bytes,
                    bool check_available) {
  const std::string key = config.vessel.enabled ? "vessel.element_size_um" : "domain.elements";
  if (estimate.largest_index_count > largest_int) {
    char count[32];
    std::snprintf(count, sizeof count, "%.3g", estimate.largest_index_count);
    throw InputError(config.source_file, key,
                     std::string("the mesh is too large for rouleau's 32-bit indices: its ") +
                         estimate.largest_index_what + " number " + count + ", above 2^31 - 1; use fewer elements");
  }
  if (!check_available || available_bytes < 0.0 || estimate.total_bytes <= available_bytes) return;
  throw InputError(config.source_file, key,
                   "the case needs about " + format_bytes(estimate.total_bytes) + " of memory (" +
                       std::to_string(estimate.fluid_nodes) + " fluid nodes; largest part: " +
                       estimate.terms.front().first + ", " + format_bytes(estimate.terms.front().second) +
                       "), more than the " + format_bytes(available_bytes) +
                       " this machine has available; use fewer elements, or --no-memory-check to go ahead anyway");
}

}  // namespace rouleau
