// Throughput of the Morse cell–cell surface interaction (paper eqs. 3, 4, 11): the pair
// kernel with a full or a half neighbour list, the kernel with the energy, and the
// neighbour-list build, on a dense packing of 2 to 1000 normal red cells; and the point
// set written out for the comparison with LAMMPS (bench/morse_vs_lammps.py).
//
//   BM_MorsePairs/cells/list/quadrature
//        SurfaceInteraction::compute_forces() with the list already built: the gather of
//        the point positions, the skin check, the pair loop (list 0: full list, each pair
//        twice, no scatter; 1: half list, each pair once, the force on j through the
//        ScatterView). quadrature 0: the surface nodes; 1: 3 Gauss points per surface
//        triangle (the case default for this mesh; 6× the points, 36× the pairs; up to
//        100 cells)
//   BM_MorsePairsAndEnergy/cells      compute_forces_and_energy() with the production
//                                     list (SurfaceInteraction's default), nodes
//   BM_MorseForceChange/cells/list/quadrature
//        SurfaceInteraction::force_change(): the exact stiffness action K δx of the
//        semi-implicit coupling (kernels/morse_stiffness.hpp), after linearize()
//   BM_NeighborListBuild/cells/list/quadrature
//        rebuild(): broad phase, bins, sort, count, scan, fill
//
//   bench_morse --write-points=FILE --cells=N [--quadrature=nodes|gauss3]
//       writes the packing's surface points, one line "x y z cell" (μm, cell from 0),
//       and exits without running the benchmarks.
//
// Packing: normal cells (hollow shell, paper preset mesh) stacked face to face along z,
// 3.96 μm between centres (the paper's rouleau spacing; the cell is at most 2.57 μm
// thick, so stacked cells leave a 1.39 μm gap at the rim and 3.15 μm on the axis), 10
// per stack (N per stack below 10), the stacks on a square x–y grid 8.2 μm apart (the
// diameter is 7.82 μm: 0.38 μm between rims). Potential: De = 1 pN/μm³, β = 4 /μm,
// r0 = 0.25 μm, r_c = 3 μm; skin 0.3 μm. The positions never change, so no rebuild
// happens inside the timed loops (checked: the run stops with an error otherwise).
//
// Counters. "pairs" is the number of UNIQUE pairs of surface points of different cells
// closer than r_c, counted once at setup from a half list by distance (and checked
// against the full list, which must hold each of them twice) — the same count as the
// LAMMPS comparison (pairs inside the cut-off, intra-cell pairs excluded). pairs/s and
// ns/pair are per unique pair for both lists, so the full list's doubled work shows
// as a higher ns/pair. list_entries (the list holds the pairs within r_c + skin),
// points, rebuilds (the list builds so far, unchanged by the timed loop).
// Byte model ("GB/s"): the list's column indices read once (4 bytes per entry) and per
// point its kind (1 int), position and weight read, its force written (7 doubles); the
// gathers of neighbour positions are assumed to hit the cache; the gather of the point
// positions from the nodes and the ScatterView's per-thread copies are not counted.
#include <benchmark/benchmark.h>

#include <Kokkos_Core.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "cells/cell_population.hpp"
#include "cells/surface_interaction.hpp"
#include "cells/surface_quadrature.hpp"
#include "config/cell_kinds.hpp"
#include "geometry/cell_mesh.hpp"
#include "kernels/morse.hpp"

namespace {

using rouleau::CellPopulation;
using rouleau::MorsePotential;
using rouleau::SurfaceInteraction;
using rouleau::bench::bytes_per_double;
using rouleau::bench::bytes_per_int;
using rouleau::bench::time_applications;

constexpr double stack_spacing = 3.96;  // [μm] between centres of stacked cells (the paper's rouleau)
constexpr double grid_spacing = 8.2;    // [μm] between stack axes (diameter 7.82 μm)
constexpr int cells_per_stack = 10;
constexpr double skin = 0.3;            // [μm]

// De [pN/μm³], β [1/μm], r0 [μm], r_c [μm]. The timing does not depend on De.
MorsePotential bench_potential() { return {1.0, 4.0, 0.25, 3.0}; }

const rouleau::CellMesh& normal_cell_mesh() {
  static const rouleau::CellMesh mesh = [] {
    const auto kinds = rouleau::builtin_cell_kinds();
    return rouleau::cell_mesh(kinds.front(), rouleau::default_mesh_cache_dir());
  }();
  return mesh;
}

// Cell c: layer c % h of stack c / h (h = min(N, 10) cells per stack), the stacks filled
// row by row on a g × g grid, g = ⌈√(number of stacks)⌉. N = 1000: 10 × 10 stacks of 10.
std::vector<rouleau::PlacedCell> packed_cells(int count) {
  const auto normal = rouleau::builtin_cell_kinds().front();
  const int per_stack = count < cells_per_stack ? count : cells_per_stack;
  const int stacks = (count + per_stack - 1) / per_stack;
  int side = 1;
  while (side * side < stacks) ++side;
  std::vector<rouleau::PlacedCell> cells(count);
  for (int c = 0; c < count; ++c) {
    const int stack = c / per_stack;
    cells[c].mesh = &normal_cell_mesh();
    cells[c].material = rouleau::NeoHookeanMaterial::from_moduli(normal.shear_modulus, normal.bulk_modulus);
    cells[c].center = {grid_spacing * (stack % side), grid_spacing * (stack / side), stack_spacing * (c % per_stack)};
  }
  return cells;
}

// quadrature 0: the surface nodes with their area weights; 1: 3 Gauss points per outer
// surface triangle (what interaction.quadrature = "auto" picks for the paper mesh, whose
// nodes are about 0.5 μm > 1/β apart).
rouleau::SurfaceQuadrature quadrature_of(int quadrature) {
  return quadrature == 0 ? rouleau::SurfaceQuadrature::nodes : rouleau::SurfaceQuadrature::gauss3;
}
const char* quadrature_name(int quadrature) { return quadrature == 0 ? "nodes" : "3 Gauss points per triangle"; }

// The points are gathered (x_p from the nodes) before anything reads them.
std::unique_ptr<SurfaceInteraction> make_interaction(const CellPopulation& cells, bool half_list, int quadrature) {
  auto interaction = std::make_unique<SurfaceInteraction>(cells, std::vector<int>(cells.num_cells(), 0), 1,
                                                          std::vector<MorsePotential>{bench_potential()}, skin,
                                                          half_list, quadrature_of(quadrature));
  interaction->gather_point_positions();
  return interaction;
}

// The list entries (i, j) with |x_i − x_j| < r_c.
long long entries_within_cutoff(const SurfaceInteraction& interaction) {
  auto positions = interaction.point_positions();
  auto offsets = interaction.neighbor_offsets();
  auto neighbors = interaction.neighbors();
  const double cutoff_squared = bench_potential().cutoff * bench_potential().cutoff;
  long long count = 0;
  Kokkos::parallel_reduce(
      "bench::morse::entries_within_cutoff", interaction.num_points(),
      KOKKOS_LAMBDA(const int i, long long& sum) {
        for (int k = offsets(i); k < offsets(i + 1); ++k) {
          const int j = neighbors(k);
          double r_squared = 0.0;
          for (int c = 0; c < 3; ++c) {
            const double d = positions(i, c) - positions(j, c);
            r_squared += d * d;
          }
          if (r_squared < cutoff_squared) ++sum;
        }
      },
      count);
  return count;
}

// The packing and its interactions (made when first asked for).
struct MorseProblem {
  int count, quadrature;
  CellPopulation cells;
  long long unique_pairs = 0;      // pairs of points of different cells closer than r_c
  int half_list_entries = 0;       // to tell which list the production default is
  std::unique_ptr<SurfaceInteraction> lists[2];  // full, half
  std::unique_ptr<SurfaceInteraction> production;

  // The unique pairs are counted from the half list (kept for BM_MorsePairs).
  MorseProblem(int n, int q) : count(n), quadrature(q), cells(packed_cells(n)) {
    lists[1] = make_interaction(cells, true, quadrature);
    lists[1]->rebuild();
    unique_pairs = entries_within_cutoff(*lists[1]);
    half_list_entries = lists[1]->num_list_entries();
  }
  SurfaceInteraction& list(int half) {
    if (!lists[half]) {
      lists[half] = make_interaction(cells, half == 1, quadrature);
      lists[half]->rebuild();
      if (entries_within_cutoff(*lists[half]) != 2 * unique_pairs)
        throw std::logic_error("bench_morse: the full list does not hold each unique pair twice");
    }
    return *lists[half];
  }
  SurfaceInteraction& production_list() {
    if (!production) {
      // the constructor's default list
      production = std::make_unique<SurfaceInteraction>(cells, std::vector<int>(cells.num_cells(), 0), 1,
                                                        std::vector<MorsePotential>{bench_potential()}, skin);
      production->gather_point_positions();
      production->rebuild();
    }
    return *production;
  }
  const char* production_name() { return production_list().num_list_entries() == half_list_entries ? "half" : "full"; }
};

std::unique_ptr<MorseProblem> cached_problem;

MorseProblem& problem(int count, int quadrature = 0) {
  if (!cached_problem || cached_problem->count != count || cached_problem->quadrature != quadrature) {
    cached_problem.reset();
    cached_problem = std::make_unique<MorseProblem>(count, quadrature);
  }
  return *cached_problem;
}

double kernel_bytes(const SurfaceInteraction& interaction) {
  return interaction.num_list_entries() * bytes_per_int +
         interaction.num_points() * (1.0 * bytes_per_int + 7.0 * bytes_per_double);
}

void set_pair_counters(benchmark::State& state, const MorseProblem& p, const SurfaceInteraction& interaction) {
  const double applications = static_cast<double>(state.iterations());
  const double pairs = static_cast<double>(p.unique_pairs);
  state.counters["pairs/s"] = benchmark::Counter(applications * pairs, benchmark::Counter::kIsRate);
  // time / (applications · pairs · 1e-9) = ns per unique pair
  state.counters["ns/pair"] =
      benchmark::Counter(applications * pairs * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["GB/s"] =
      benchmark::Counter(applications * kernel_bytes(interaction) * 1e-9, benchmark::Counter::kIsRate);
  state.counters["pairs"] = pairs;
  state.counters["list_entries"] = interaction.num_list_entries();
  state.counters["points"] = interaction.num_points();
  state.counters["rebuilds"] = interaction.rebuild_count();
}

// Times `apply` and stops with an error if it rebuilt the list.
template <class Apply>
bool time_without_rebuild(benchmark::State& state, SurfaceInteraction& interaction, const Apply& apply) {
  const int rebuilds = interaction.rebuild_count();
  time_applications(state, apply);
  if (interaction.rebuild_count() != rebuilds) {
    state.SkipWithError("the list was rebuilt inside the timed loop");
    return false;
  }
  return true;
}

void BM_MorsePairs(benchmark::State& state) {
  const int quadrature = static_cast<int>(state.range(2));
  MorseProblem& p = problem(static_cast<int>(state.range(0)), quadrature);
  const int half = static_cast<int>(state.range(1));
  SurfaceInteraction& interaction = p.list(half);
  if (!time_without_rebuild(state, interaction, [&] { interaction.compute_forces(); })) return;
  state.SetLabel(std::string(half ? "half list, ScatterView" : "full list") + "; " + quadrature_name(quadrature));
  set_pair_counters(state, p, interaction);
}

void BM_MorsePairsAndEnergy(benchmark::State& state) {
  MorseProblem& p = problem(static_cast<int>(state.range(0)));
  SurfaceInteraction& interaction = p.production_list();
  double energy = 0.0;
  if (!time_without_rebuild(state, interaction, [&] { energy = interaction.compute_forces_and_energy(); })) return;
  state.SetLabel(std::string(p.production_name()) + " list (production default)");
  state.counters["energy_pN_um"] = energy;
  set_pair_counters(state, p, interaction);
}

// The interaction's stiffness action K δx (the semi-implicit coupling's inner loop): the
// list's coefficients found once (linearize(), not timed), then force_change() of fixed
// node moves: gather of the point moves, the pair stream, the scatter to the nodes.
// Byte model: per pair within the cut-off (linearize() keeps those of the list's entries)
// its column (4 bytes) and coefficients (16); per point its position and move read and
// its change written (9 doubles); neighbour gathers assumed to hit the cache.
void BM_MorseForceChange(benchmark::State& state) {
  const int quadrature = static_cast<int>(state.range(2));
  MorseProblem& p = problem(static_cast<int>(state.range(0)), quadrature);
  const int half = static_cast<int>(state.range(1));
  SurfaceInteraction& interaction = p.list(half);
  interaction.linearize();
  const int nodes = p.cells.num_nodes();
  CellPopulation::NodeVectors moves("rouleau::bench::node_moves", nodes), changes("rouleau::bench::changes", nodes);
  {
    auto h = Kokkos::create_mirror_view(moves);
    for (int n = 0; n < nodes; ++n)
      for (int c = 0; c < 3; ++c) h(n, c) = std::sin(0.37 * n + c);
    Kokkos::deep_copy(moves, h);
  }
  if (!time_without_rebuild(state, interaction, [&] { interaction.force_change(moves, changes); })) return;
  state.SetLabel(std::string(half ? "half list, ScatterView" : "full list") + "; " + quadrature_name(quadrature));
  set_pair_counters(state, p, interaction);
  const double bytes = interaction.linearized_pairs() * (bytes_per_int + 2.0 * bytes_per_double) +
                       interaction.num_points() * 9.0 * bytes_per_double;
  state.counters["GB/s"] = benchmark::Counter(state.iterations() * bytes * 1e-9, benchmark::Counter::kIsRate);
}

void BM_NeighborListBuild(benchmark::State& state) {
  MorseProblem& p = problem(static_cast<int>(state.range(0)), static_cast<int>(state.range(2)));
  const int half = static_cast<int>(state.range(1));
  SurfaceInteraction& interaction = p.list(half);
  time_applications(state, [&] { interaction.rebuild(); });
  state.SetLabel(std::string(half ? "half list" : "full list") + "; " + quadrature_name(p.quadrature));
  const double applications = static_cast<double>(state.iterations());
  state.counters["points/s"] = benchmark::Counter(applications * interaction.num_points(), benchmark::Counter::kIsRate);
  state.counters["list_entries/s"] =
      benchmark::Counter(applications * interaction.num_list_entries(), benchmark::Counter::kIsRate);
  state.counters["points"] = interaction.num_points();
  state.counters["list_entries"] = interaction.num_list_entries();
  state.counters["active_cells"] = interaction.active_cell_count();
}

void cell_counts(benchmark::internal::Benchmark* b) {
  b->ArgName("cells")->Arg(2)->Arg(10)->Arg(100)->Arg(1000)->UseManualTime()->Unit(benchmark::kMillisecond);
}

// cells × list (0 full, 1 half) × quadrature (0 nodes, 1 Gauss points: 36 times the pairs,
// so not at 1000 cells, whose list would take 14 GB).
void cells_lists_quadratures(benchmark::internal::Benchmark* b) {
  b->ArgNames({"cells", "list", "quadrature"});
  for (int quadrature : {0, 1})
    for (int cells : {2, 10, 100, 1000})
      for (int list : {0, 1})
        if (quadrature == 0 || cells <= 100) b->Args({cells, list, quadrature});
  b->UseManualTime()->Unit(benchmark::kMillisecond);
}

// Writes the packing's surface points ("x y z cell", cells from 0) to `path`.
void write_points(const std::string& path, int count, int quadrature) {
  const CellPopulation cells(packed_cells(count));
  const auto interaction = make_interaction(cells, false, quadrature);
  auto positions = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), interaction->point_positions());
  auto point_cell = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), interaction->point_cell());
  const std::string temporary = path + ".tmp";
  std::FILE* file = std::fopen(temporary.c_str(), "w");
  if (!file) throw std::runtime_error("bench_morse --write-points: cannot open " + temporary);
  for (int i = 0; i < interaction->num_points(); ++i)
    std::fprintf(file, "%.17g %.17g %.17g %d\n", positions(i, 0), positions(i, 1), positions(i, 2), point_cell(i));
  if (std::fclose(file) != 0 || std::rename(temporary.c_str(), path.c_str()) != 0)
    throw std::runtime_error("bench_morse --write-points: cannot write " + path);
}

}  // namespace

BENCHMARK(BM_MorsePairs)->Apply(cells_lists_quadratures);
BENCHMARK(BM_MorsePairsAndEnergy)->Apply(cell_counts);
BENCHMARK(BM_MorseForceChange)->Apply(cells_lists_quadratures);
BENCHMARK(BM_NeighborListBuild)->Apply(cells_lists_quadratures);

int main(int argc, char** argv) {
  // --write-points=FILE, --cells=N and --quadrature=nodes|gauss3 are ours: taken out of
  // argv before Kokkos and Google Benchmark see it.
  std::string points_path;
  int points_cells = 0, points_quadrature = 0;
  int kept = 1;
  for (int a = 1; a < argc; ++a) {
    if (std::strncmp(argv[a], "--write-points=", 15) == 0)
      points_path = argv[a] + 15;
    else if (std::strncmp(argv[a], "--cells=", 8) == 0)
      points_cells = std::atoi(argv[a] + 8);
    else if (std::strcmp(argv[a], "--quadrature=gauss3") == 0)
      points_quadrature = 1;
    else if (std::strcmp(argv[a], "--quadrature=nodes") == 0)
      points_quadrature = 0;
    else
      argv[kept++] = argv[a];
  }
  argc = kept;
  argv[argc] = nullptr;

  Kokkos::ScopeGuard kokkos(argc, argv);
  if (!points_path.empty()) {
    if (points_cells < 1) {
      std::fprintf(stderr, "bench_morse: --write-points needs --cells=N with N >= 1\n");
      return 2;
    }
    try {
      write_points(points_path, points_cells, points_quadrature);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "%s\n", error.what());
      return 1;
    }
    return 0;
  }
  const auto morse_context = [] {
    const auto& mesh = normal_cell_mesh();
    std::set<int> surface_nodes;
    for (const auto& triangle : mesh.outer_surface) surface_nodes.insert(triangle.begin(), triangle.end());
    benchmark::AddCustomContext("cell_mesh", "normal RBC, hollow shell, paper preset: " +
                                                 std::to_string(mesh.nodes.size()) + " nodes, " +
                                                 std::to_string(mesh.tetrahedra.size()) + " tetrahedra, " +
                                                 std::to_string(surface_nodes.size()) + " surface nodes, " +
                                                 std::to_string(mesh.outer_surface.size()) +
                                                 " outer-surface triangles (x3 Gauss points)");
    benchmark::AddCustomContext("packing", "stacks of 10 (N<10: one stack of N) along z, 3.96 um between centres; "
                                           "stacks 8.2 um apart on a square x-y grid");
    benchmark::AddCustomContext("morse", "De 1 pN/um^3, beta 4 /um, r0 0.25 um, cut-off 3 um, skin 0.3 um");
  };
  return rouleau::bench::run_benchmarks(argc, argv, morse_context, [] { cached_problem.reset(); });
}
