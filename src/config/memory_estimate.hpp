#pragma once
// The memory a case needs, estimated before any work from the sizes the code allocates
// by, and the memory this machine has available: `rouleau check` prints both, and
// `rouleau check` and `rouleau run` refuse a case that does not fit (exit 2) unless told
// to go ahead (--no-memory-check).
//
// The estimate is a sum of named terms, each the bytes of the arrays one part of the code
// allocates (the file that allocates them is named beside each term in memory_estimate.cpp):
// the fluid mesh and its element geometry, the fluid state and the GMRES basis, the
// preconditioner (the Jacobian's 4x4 blocks, ILU(0) factors, multigrid levels, ILU's
// level-schedule scratch), the cells and their coupling, the Morse lists, and the output
// copies. It is checked against measured peak memory (bench/memory_estimate.py).
//
// A vessel's tetrahedra are counted from its element-size field before Gmsh meshes it, and
// the cells' nodes from their kinds' mesh resolution (the normal red cell's counts at each
// preset). The Morse lists depend on how close the cells come; the estimate takes an
// aggregate's density. It is the memory of one process on the host: a GPU build keeps the
// large arrays in the device's memory, which this does not check, and under mpirun each
// rank is held to the whole case's estimate.
// Host-only: includes no Kokkos header.
#include <string>
#include <utility>
#include <vector>

#include "config/case_config.hpp"

namespace rouleau {

struct MemoryEstimate {
  long long fluid_nodes = 0;      // nodes carrying unknowns (a periodic pair counts once)
  long long fluid_elements = 0;
  long long cell_nodes = 0;
  double jacobian_blocks = 0.0;    // 4x4 blocks of the assembled Jacobian's graph
  double widest_ilu_level = 0.0;   // rows of the widest level of ILU(0)'s schedule
  // (what, bytes), the largest first.
  std::vector<std::pair<std::string, double>> terms;
  double total_bytes = 0.0;
  // The largest count the code holds in a 32-bit index for this case, and what it counts:
  // above 2^31 − 1 the case cannot run whatever the memory.
  double largest_index_count = 0.0;
  std::string largest_index_what;
};

// The estimate for `config` run on `threads` host threads (each thread holds its own copy
// of the scattered sums).
MemoryEstimate estimate_memory(const CaseConfig& config, int threads);

// The bytes this process may still use: MemAvailable of /proc/meminfo, or less when a
// cgroup v2 (a container, a batch job) limits this process's group or one above it; a
// negative value when neither can be read.
double available_memory_bytes();

// "1.23 GiB", "45.6 MiB", "456 KiB": three significant digits in binary units.
std::string format_bytes(double bytes);

// The estimate in a few lines: the total, then the largest terms.
std::string describe_memory(const MemoryEstimate& estimate, double available_bytes);

// Throws InputError(case file, the key that sizes the mesh, reason) when a 32-bit index
// would overflow (always), or when `check_available` and the estimate exceeds
// `available_bytes` (when that is known, i.e. >= 0): the estimate and the available memory
// named, with the way out (a coarser case, or --no-memory-check).
void require_memory(const CaseConfig& config, const MemoryEstimate& estimate, double available_bytes,
                    bool check_available);

}  // namespace rouleau
