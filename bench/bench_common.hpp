#pragma once
// What every rouleau benchmark shares: fenced manual timing, the STREAM-like triad that
// gives the machine's achievable memory bandwidth in the same run, and the Kokkos
// configuration in the benchmark context.
#include <benchmark/benchmark.h>

#include <Kokkos_Core.hpp>
#include <cstdint>
#include <string>

namespace rouleau::bench {

constexpr double bytes_per_double = 8.0;
constexpr double bytes_per_int = 4.0;

// Times `apply` (after one warm-up call: first touch, allocations) with fences around
// each timed application.
template <class Apply>
void time_applications(benchmark::State& state, const Apply& apply) {
  apply();
  Kokkos::fence();
  for (auto _ : state) {
    Kokkos::fence();
    Kokkos::Timer timer;
    apply();
    Kokkos::fence();
    state.SetIterationTime(timer.seconds());
  }
}

// STREAM triad a = b + s·c over `bytes` (three arrays of bytes/24 doubles; 3 × 8 bytes
// per entry, the STREAM convention, no write-allocate), reported as GB/s.
inline void triad(benchmark::State& state, double bytes) {
  const auto length = static_cast<std::int64_t>(bytes / (3 * bytes_per_double));
  Kokkos::View<double*> a("bench::triad::a", length), b("bench::triad::b", length), c("bench::triad::c", length);
  Kokkos::deep_copy(b, 1.0);
  Kokkos::deep_copy(c, 2.0);
  const double s = 3.0;
  using Policy = Kokkos::RangePolicy<Kokkos::DefaultExecutionSpace, Kokkos::IndexType<std::int64_t>>;
  time_applications(state, [&] {
    Kokkos::parallel_for(
        "bench::triad", Policy(0, length), KOKKOS_LAMBDA(const std::int64_t i) { a(i) = b(i) + s * c(i); });
  });
  const double moved = 3.0 * bytes_per_double * static_cast<double>(length);
  state.counters["GB/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * moved * 1e-9, benchmark::Counter::kIsRate);
  state.counters["MB/application"] = moved * 1e-6;
}

// The machine's achievable floating-point rate for this build (compiler flags, vector
// width): every thread runs 24 independent chains of x = x·a + b in doubles, long enough
// that memory plays no part; 2 flops per link (a multiply and an add, or one FMA where
// the build allows it). Reported as GFLOP/s, the roof the compute-bound kernels meet.
inline void peak_flops(benchmark::State& state) {
  constexpr int chains = 24, links = 4096;
  const int items = 64 * Kokkos::DefaultExecutionSpace().concurrency();
  Kokkos::View<double*> sink("bench::peak_flops::sink", items);
  time_applications(state, [&] {
    Kokkos::parallel_for(
        "bench::peak_flops", Kokkos::RangePolicy<Kokkos::DefaultExecutionSpace>(0, items),
        KOKKOS_LAMBDA(const int i) {
          double x[chains];
          for (int c = 0; c < chains; ++c) x[c] = 1.0 + 1e-3 * (i + c);
          const double a = 0.999999, b = 1e-7;
          for (int k = 0; k < links; ++k)
            for (int c = 0; c < chains; ++c) x[c] = x[c] * a + b;
          double sum = 0.0;
          for (int c = 0; c < chains; ++c) sum += x[c];
          sink(i) = sum;
        });
  });
  const double flops = 2.0 * chains * links * static_cast<double>(items);
  state.counters["GFLOP/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * flops * 1e-9, benchmark::Counter::kIsRate);
}

// The Kokkos execution space, its concurrency and the Kokkos version, in the context.
inline void add_kokkos_context() {
  using Space = Kokkos::DefaultExecutionSpace;
  benchmark::AddCustomContext("kokkos_execution_space", Space::name());
  benchmark::AddCustomContext("kokkos_concurrency", std::to_string(Space().concurrency()));
  benchmark::AddCustomContext("kokkos_version", std::to_string(KOKKOS_VERSION / 10000) + "." +
                                                    std::to_string(KOKKOS_VERSION / 100 % 100) + "." +
                                                    std::to_string(KOKKOS_VERSION % 100));
}

// The common body of a benchmark program's main, inside its Kokkos scope: Google
// Benchmark's options, the Kokkos context and `extra_context()`, the run, and then
// `release()` of the Views the benchmarks cached (they must go before Kokkos::finalize).
// Returns main's exit code.
template <class ExtraContext, class Release>
int run_benchmarks(int& argc, char** argv, const ExtraContext& extra_context, const Release& release) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  add_kokkos_context();
  extra_context();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  release();
  return 0;
}

}  // namespace rouleau::bench
