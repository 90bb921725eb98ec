// Throughput of the RKPM transfer (paper eqs. 15, 16) between the fluid mesh and solid
// points: the setup (supports and shape functions) and the two applications.
//
//   BM_RkpmUpdate/points/correct        coupler.update(points) (correct 1: the linear
//                                       correction forced at every point; 0: only where
//                                       needed — nowhere in this uniform periodic box)
//   BM_RkpmInterpolate/points/correct   coupler.interpolate(): a pure gather
//   BM_RkpmSpread/points/correct        coupler.spread(): its transpose, through a ScatterView
//
// Fluid: a uniform 40 × 20 × 20 μm shear box of 32 × 16 × 16 hexahedra (h = 1.25 μm),
// periodic in x and z; points random in its middle half along y (away from the walls),
// as the surface and volume nodes of cells would be. About 64 fluid nodes per point.
// Byte model ("GB/s"), per point and application: its row (node index and shape function,
// 12 bytes per entry) and, for interpolation, 3 gathered doubles per entry and 3 written;
// for spreading, 3 read and 3 doubles scattered per entry.
#include <benchmark/benchmark.h>

#include <Kokkos_Core.hpp>
#include <memory>
#include <random>

#include "bench_common.hpp"
#include "coupling/rkpm_coupler.hpp"
#include "mesh/fluid_mesh.hpp"

namespace {

using rouleau::RkpmCoupler;
using rouleau::bench::bytes_per_double;
using rouleau::bench::bytes_per_int;
using rouleau::bench::time_applications;

struct RkpmProblem {
  int count;
  bool correct;
  rouleau::FluidMesh mesh;
  RkpmCoupler coupler;
  RkpmCoupler::PointVectors points, values;
  Kokkos::View<double*> nodal;

  RkpmProblem(int n, bool force_correction)
      : count(n),
        correct(force_correction),
        mesh(rouleau::make_box_mesh({0, 0, 0}, {40, 20, 20}, {32, 16, 16}, {1, 1, 1}, {true, false, true})),
        coupler(mesh),
        points("bench::points", n),
        values("bench::values", n),
        nodal("bench::nodal", 4 * mesh.num_dof_nodes) {
    std::mt19937 rng(20241122);
    std::uniform_real_distribution<double> x(0, 40), y(5, 15), z(0, 20);
    auto h = Kokkos::create_mirror_view(points);
    for (int p = 0; p < n; ++p) {
      h(p, 0) = x(rng);
      h(p, 1) = y(rng);
      h(p, 2) = z(rng);
    }
    Kokkos::deep_copy(points, h);
    Kokkos::deep_copy(nodal, 1.0);
    Kokkos::deep_copy(values, 1.0);
    coupler.always_correct(force_correction);
    coupler.update(points);
  }
  double entries() const { return static_cast<double>(Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), coupler.offsets())(count)); }
};

std::unique_ptr<RkpmProblem> cached;

RkpmProblem& problem(int count, bool correct) {
  if (!cached || cached->count != count || cached->correct != correct) {
    cached.reset();
    cached = std::make_unique<RkpmProblem>(count, correct);
  }
  return *cached;
}

void set_counters(benchmark::State& state, double points, double entries) {
  const double applications = static_cast<double>(state.iterations());
  const double bytes = entries * (bytes_per_int + bytes_per_double + 3 * bytes_per_double) + points * 3 * bytes_per_double;
  state.counters["points/s"] = benchmark::Counter(applications * points, benchmark::Counter::kIsRate);
  state.counters["GB/s"] = benchmark::Counter(applications * bytes * 1e-9, benchmark::Counter::kIsRate);
  state.counters["entries_per_point"] = entries / points;
}

void BM_RkpmUpdate(benchmark::State& state) {
  RkpmProblem& p = problem(static_cast<int>(state.range(0)), state.range(1) != 0);
  time_applications(state, [&] { p.coupler.update(p.points); });
  state.counters["points/s"] = benchmark::Counter(static_cast<double>(state.iterations()) * p.count,
                                                  benchmark::Counter::kIsRate);
  state.counters["corrected_points"] = p.coupler.corrected_points();
}

void BM_RkpmInterpolate(benchmark::State& state) {
  RkpmProblem& p = problem(static_cast<int>(state.range(0)), state.range(1) != 0);
  time_applications(state, [&] { p.coupler.interpolate(p.nodal, 4, p.values); });
  set_counters(state, p.count, p.entries());
}

void BM_RkpmSpread(benchmark::State& state) {
  RkpmProblem& p = problem(static_cast<int>(state.range(0)), state.range(1) != 0);
  time_applications(state, [&] { p.coupler.spread(p.values, p.nodal, 4); });
  set_counters(state, p.count, p.entries());
}

void sizes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"points", "correct"})
      ->ArgsProduct({{1000, 10000, 100000}, {0, 1}})
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
}

}  // namespace

BENCHMARK(BM_RkpmUpdate)->Apply(sizes);
BENCHMARK(BM_RkpmInterpolate)->Apply(sizes);
BENCHMARK(BM_RkpmSpread)->Apply(sizes);

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  return rouleau::bench::run_benchmarks(argc, argv, [] {}, [] { cached.reset(); });
}
