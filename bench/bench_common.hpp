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
