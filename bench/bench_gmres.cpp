// The vector work of a GMRES iteration against the machine's memory bandwidth: the CGS2
// orthogonalization of a new Krylov vector against the basis, its norm and its scaling.
//
//   BM_Orthogonalize/nodes_per_edge/columns       rouleau::GramSchmidt (what Gmres runs):
//                                                 three fused sweeps over V, then w ← w/‖w‖
//   BM_OrthogonalizeBlas/nodes_per_edge/columns   the baseline, as Gmres did it before: four
//                                                 KokkosBlas gemv sweeps, nrm2, scal
//   BM_Triad/nodes_per_edge/columns               the STREAM triad over the model's bytes
//
// n = 4 (nodes_per_edge)³ unknowns, the fluid vector of a box of that many nodes; the
// columns are the iteration's position in the restart cycle (GMRES(60) averages ~30, the
// scenes converge in 6–20). V has orthonormal columns (QR of a random matrix) and w is
// random, so both passes do full work.
//
// Byte model, per iteration (doubles of 8 bytes; c = columns): what CGS2 must move at
// least. Pass 1's projection needs all of w before any update, and pass 2's all of the
// updated w, so V is read three times: c1 = Vᵀw reads V and w (n c + n); the update with
// c1 and the projection c2 read V once more and read and write w (n c + 2 n); the update
// with c2 and the norm read V, read and write w (n c + 2 n); the scaling reads and writes
// w (2 n). Total 3 n c + 7 n doubles, the same model for both variants (the baseline
// moves more: 4 n c + 9 n). Flops: 8 n c + 3 n. Below 1 flop per byte: bandwidth-bound,
// its roof is the triad's GB/s over the same bytes.
#include <benchmark/benchmark.h>

#include <Kokkos_Core.hpp>
#include <Kokkos_Random.hpp>
#include <KokkosBlas1_nrm2.hpp>
#include <KokkosBlas1_scal.hpp>
#include <KokkosBlas2_gemv.hpp>
#include <memory>
#include <vector>

#include "bench_common.hpp"
#include "solver/gram_schmidt.hpp"

namespace {

using rouleau::bench::bytes_per_double;
using rouleau::bench::time_applications;

using Basis = Kokkos::View<double**, Kokkos::LayoutLeft>;

struct KrylovProblem {
  int nodes_per_edge, columns;
  long n;
  Basis basis;                 // V: n × columns, orthonormal
  Kokkos::View<double*> w, w_start, coefficients;
  Kokkos::View<double*>::HostMirror coefficients_host;
  std::vector<double> h;
  rouleau::GramSchmidt gram_schmidt;

  KrylovProblem(int edge, int c)
      : nodes_per_edge(edge),
        columns(c),
        n(4L * edge * edge * edge),
        basis("bench::V", n, c),
        w("bench::w", n),
        w_start("bench::w_start", n),
        coefficients("bench::coefficients", c),
        coefficients_host(Kokkos::create_mirror_view(coefficients)),
        h(c),
        gram_schmidt(n, c) {
    Kokkos::Random_XorShift64_Pool<> pool(20261124);
    Kokkos::fill_random(basis, pool, -1.0, 1.0);
    Kokkos::fill_random(w_start, pool, -1.0, 1.0);
    // Orthonormal columns by CGS2 itself, column by column.
    for (int j = 0; j < c; ++j) {
      auto v = Kokkos::subview(basis, Kokkos::ALL(), j);
      const double norm = j == 0 ? KokkosBlas::nrm2(v)
                                 : gram_schmidt.orthogonalize(
                                       Kokkos::subview(basis, Kokkos::ALL(), Kokkos::make_pair(0, j)), v, h.data());
      KokkosBlas::scal(v, 1.0 / norm, v);
    }
  }
  // One iteration's vector work.
  void iterate() {
    const double norm = gram_schmidt.orthogonalize(basis, w, h.data());
    KokkosBlas::scal(w, 1.0 / norm, w);
  }
  // The same through KokkosBlas, as Gmres did it before GramSchmidt.
  void iterate_blas() {
    for (int pass = 0; pass < 2; ++pass) {
      KokkosBlas::gemv("T", 1.0, basis, w, 0.0, coefficients);
      KokkosBlas::gemv("N", -1.0, basis, coefficients, 1.0, w);
      Kokkos::deep_copy(coefficients_host, coefficients);
      for (int j = 0; j < columns; ++j) h[j] += coefficients_host(j);
    }
    const double norm = KokkosBlas::nrm2(w);
    KokkosBlas::scal(w, 1.0 / norm, w);
  }
  double doubles_moved() const { return 3.0 * n * columns + 7.0 * n; }
  double flops() const { return 8.0 * n * columns + 3.0 * n; }
};

std::unique_ptr<KrylovProblem> cached;

KrylovProblem& problem(int edge, int columns) {
  if (!cached || cached->nodes_per_edge != edge || cached->columns != columns) {
    cached.reset();
    cached = std::make_unique<KrylovProblem>(edge, columns);
  }
  return *cached;
}

// Times `iterate` on a fresh copy of w each time (restored outside the timed region).
template <class Iterate>
void time_iterations(benchmark::State& state, KrylovProblem& p, const Iterate& iterate) {
  Kokkos::deep_copy(p.w, p.w_start);
  iterate();
  Kokkos::fence();
  for (auto _ : state) {
    Kokkos::deep_copy(p.w, p.w_start);
    Kokkos::fence();
    Kokkos::Timer timer;
    iterate();
    Kokkos::fence();
    state.SetIterationTime(timer.seconds());
  }
  const double iterations = static_cast<double>(state.iterations());
  state.counters["GB/s"] =
      benchmark::Counter(iterations * p.doubles_moved() * bytes_per_double * 1e-9, benchmark::Counter::kIsRate);
  state.counters["GFLOP/s"] = benchmark::Counter(iterations * p.flops() * 1e-9, benchmark::Counter::kIsRate);
  state.counters["MB/iteration"] = p.doubles_moved() * bytes_per_double * 1e-6;
  state.counters["unknowns"] = static_cast<double>(p.n);
}

void BM_Orthogonalize(benchmark::State& state) {
  auto& p = problem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  time_iterations(state, p, [&] { p.iterate(); });
}

void BM_OrthogonalizeBlas(benchmark::State& state) {
  auto& p = problem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  time_iterations(state, p, [&] { p.iterate_blas(); });
}

void BM_Triad(benchmark::State& state) {
  const double n = 4.0 * state.range(0) * state.range(0) * state.range(0);
  const double columns = static_cast<double>(state.range(1));
  rouleau::bench::triad(state, (3.0 * n * columns + 7.0 * n) * bytes_per_double);
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int edge : {17, 33, 65})
    for (int columns : {1, 10, 30, 60}) b->Args({edge, columns});
}

BENCHMARK(BM_Orthogonalize)->Apply(sizes)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_OrthogonalizeBlas)->Apply(sizes)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Triad)->Apply(sizes)->UseManualTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(rouleau::bench::peak_flops)->Name("BM_PeakFlops")->UseManualTime()->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  Kokkos::ScopeGuard guard(argc, argv);
  return rouleau::bench::run_benchmarks(argc, argv, [] {}, [] { cached.reset(); });
}
