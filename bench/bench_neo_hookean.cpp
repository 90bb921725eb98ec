// Throughput of the cells' neo-Hookean internal-force kernel (paper eqs. 2, 9, 10) on
// normal red cells at the paper's resolution, for 1 to 1000 cells, set against the
// machine's memory bandwidth measured in the same run.
//
//   BM_InternalForces/cells/scatter   the forces, as the time loop computes them each
//                                     step (scatter 0: the production ScatterView —
//                                     per-thread copies on CPU threads; 1: one buffer
//                                     updated atomically, as on GPUs)
//   BM_InternalForcesAndEnergy/cells  the forces and the strain energy (a reduction)
//   BM_Triad/cells                    a = b + s·c over the bytes BM_InternalForces moves
//
// Cells: the "normal" kind (hollow shell, paper preset mesh), placed side by side on a
// grid and each deformed by a different random affine map plus nodal jitter (so no two
// elements see the same F).
//
// Byte model ("GB/s"), the bytes a perfect implementation must move per application:
// per element the stored reference data D_m⁻¹ (9 doubles) and V0 (1 double), its 4
// node indices and its material index (5 ints); per node the current position read
// once and the force written once (6 doubles). The ScatterView's per-thread copies
// (zeroed and summed each call) are an implementation cost, not counted: the ratio to
// the triad exposes them.
//
// Flop model ("GFLOP/s"), counted by hand from kernels/neo_hookean.hpp and tet4.hpp per
// element: D_s (9) and F = D_s D_m⁻¹ (45), ∇N_0 (9), det F (14), cof F (27), I1 (17),
// J^(−2/3) (2, plus one cbrt counted as one flop), P (36), f_a = −V0 P ∇N_a and its
// accumulation (84): 244 flops; the energy adds 8.
#include <benchmark/benchmark.h>

#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>
#include <filesystem>
#include <memory>
#include <random>
#include <vector>

#include "bench_common.hpp"
#include "cells/cell_population.hpp"
#include "config/cell_kinds.hpp"
#include "geometry/cell_mesh.hpp"
#include "kernels/neo_hookean.hpp"
#include "kernels/scatter_sum.hpp"

namespace {

using rouleau::CellPopulation;
using rouleau::bench::bytes_per_double;
using rouleau::bench::bytes_per_int;
using rouleau::bench::time_applications;

constexpr double flops_per_element = 244.0;

double kernel_bytes(const CellPopulation& cells) {
  return cells.num_elements() * (10.0 * bytes_per_double + 5.0 * bytes_per_int) +
         cells.num_nodes() * 6.0 * bytes_per_double;
}

const rouleau::CellMesh& normal_cell_mesh() {
  static const rouleau::CellMesh mesh = [] {
    const auto kinds = rouleau::builtin_cell_kinds();
    return rouleau::cell_mesh(kinds.front(), rouleau::default_mesh_cache_dir());
  }();
  return mesh;
}

// `count` normal cells, 10 μm apart on a cubic grid, each randomly deformed.
struct CellsProblem {
  int count;
  CellPopulation cells;

  static std::vector<rouleau::PlacedCell> placed(int count) {
    const auto kinds = rouleau::builtin_cell_kinds();
    const auto& normal = kinds.front();
    std::vector<rouleau::PlacedCell> cells(count);
    int side = 1;
    while (side * side * side < count) ++side;
    for (int c = 0; c < count; ++c) {
      cells[c].mesh = &normal_cell_mesh();
      cells[c].material = rouleau::NeoHookeanMaterial::from_moduli(normal.shear_modulus, normal.bulk_modulus);
      cells[c].center = {10.0 * (c % side), 10.0 * (c / side % side), 10.0 * (c / (side * side))};
    }
    return cells;
  }

  explicit CellsProblem(int n) : count(n), cells(placed(n)) {
    // A copy on the host (the reference configuration stays as it is).
    auto x = Kokkos::create_mirror(Kokkos::HostSpace(), cells.reference_positions());
    Kokkos::deep_copy(x, cells.reference_positions());
    std::mt19937 rng(20241122);
    std::uniform_real_distribution<double> u(-0.1, 0.1);
    for (int c = 0; c < cells.num_cells(); ++c) {
      double f[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) f[i][j] = (i == j ? 1.0 : 0.0) + u(rng);
      const int first = cells.cell_first_node()[c];
      for (int node = first; node < first + cells.cell_node_count()[c]; ++node) {
        const double p[3] = {x(node, 0), x(node, 1), x(node, 2)};
        for (int i = 0; i < 3; ++i) x(node, i) = f[i][0] * p[0] + f[i][1] * p[1] + f[i][2] * p[2] + 0.1 * u(rng);
      }
    }
    cells.set_positions(x);
  }
};

std::unique_ptr<CellsProblem> cached_problem;

CellsProblem& problem(int count) {
  if (!cached_problem || cached_problem->count != count) {
    cached_problem.reset();
    cached_problem = std::make_unique<CellsProblem>(count);
  }
  return *cached_problem;
}

void set_counters(benchmark::State& state, const CellPopulation& cells) {
  const double applications = static_cast<double>(state.iterations());
  state.counters["elements/s"] = benchmark::Counter(applications * cells.num_elements(), benchmark::Counter::kIsRate);
  state.counters["GB/s"] =
      benchmark::Counter(applications * kernel_bytes(cells) * 1e-9, benchmark::Counter::kIsRate);
  state.counters["GFLOP/s"] =
      benchmark::Counter(applications * cells.num_elements() * flops_per_element * 1e-9, benchmark::Counter::kIsRate);
  state.counters["elements"] = cells.num_elements();
  state.counters["MB/application"] = kernel_bytes(cells) * 1e-6;
}

void BM_InternalForces(benchmark::State& state) {
  CellsProblem& p = problem(static_cast<int>(state.range(0)));
  CellPopulation& cells = p.cells;
  if (state.range(1) == 0) {
    time_applications(state, [&] { cells.compute_internal_forces(); });
    state.SetLabel("ScatterView, default (per-thread copies on CPU threads)");
  } else {
    // The same functor through a ScatterView that adds atomically into one buffer.
    using AtomicScatter =
        Kokkos::Experimental::ScatterView<double* [3], typename CellPopulation::NodeVectors::array_layout,
                                          Kokkos::DefaultExecutionSpace::device_type, Kokkos::Experimental::ScatterSum,
                                          Kokkos::Experimental::ScatterNonDuplicated, Kokkos::Experimental::ScatterAtomic>;
    AtomicScatter scatter("bench::atomic_forces", cells.num_nodes());
    CellPopulation::NodeVectors gathered("bench::gathered_forces", cells.num_nodes());
    rouleau::NeoHookeanForceFunctor<AtomicScatter> forces{
        cells.positions(), cells.element_nodes(), cells.inverse_edge_matrix(), cells.reference_volume(),
        cells.element_cell(), {}, scatter};
    Kokkos::View<rouleau::NeoHookeanMaterial*> materials("bench::materials", cells.num_cells());
    const auto normal = rouleau::builtin_cell_kinds().front();
    Kokkos::deep_copy(materials, rouleau::NeoHookeanMaterial::from_moduli(normal.shear_modulus, normal.bulk_modulus));
    forces.materials = materials;
    time_applications(state, [&] {
      scatter.reset();
      Kokkos::parallel_for("bench::internal_forces_atomic",
                           Kokkos::RangePolicy<rouleau::ForcesOnly>(0, cells.num_elements()), forces);
      rouleau::gather_into(gathered, scatter);
    });
    state.SetLabel("ScatterView, atomic");
  }
  set_counters(state, cells);
}

void BM_InternalForcesAndEnergy(benchmark::State& state) {
  CellsProblem& p = problem(static_cast<int>(state.range(0)));
  double energy = 0.0;
  time_applications(state, [&] { energy = p.cells.compute_internal_forces_and_energy(); });
  state.counters["energy_pN_um"] = energy;
  set_counters(state, p.cells);
}

void BM_Triad(benchmark::State& state) {
  CellsProblem& p = problem(static_cast<int>(state.range(0)));
  rouleau::bench::triad(state, kernel_bytes(p.cells));
}

void cell_counts(benchmark::internal::Benchmark* b) {
  b->ArgName("cells")->Arg(1)->Arg(10)->Arg(100)->Arg(1000)->UseManualTime()->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK(BM_Triad)->Apply(cell_counts);
BENCHMARK(BM_InternalForces)
    ->ArgNames({"cells", "scatter"})
    ->ArgsProduct({{1, 10, 100, 1000}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_InternalForcesAndEnergy)->Apply(cell_counts);

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  const auto mesh_context = [] {
    const auto& mesh = normal_cell_mesh();
    benchmark::AddCustomContext("cell_mesh", "normal RBC, hollow shell, paper preset: " +
                                                 std::to_string(mesh.nodes.size()) + " nodes, " +
                                                 std::to_string(mesh.tetrahedra.size()) + " tetrahedra");
  };
  return rouleau::bench::run_benchmarks(argc, argv, mesh_context, [] { cached_problem.reset(); });
}
