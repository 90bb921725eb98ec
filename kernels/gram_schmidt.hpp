#pragma once
// The sweeps of classical Gram–Schmidt applied twice (CGS2) over a Krylov basis V
// (n × c, LayoutLeft: each column contiguous), for GMRES's Arnoldi step:
//
//   sweep 1  (Project):            c1 = Vᵀ w
//   sweep 2  (SubtractAndProject): w ← w − V c1,  then  c2 = Vᵀ w
//   sweep 3  (SubtractAndNorm):    w ← w − V c2,  then  ‖w‖²
//
// so that the Hessenberg column is h = c1 + c2 and w ⟂ V to round-off. The basis is
// read three times, not four (the second pass's update and its projection share one
// read of V) and the norm rides on the last sweep. Every sweep is bound by memory
// bandwidth.
//
// The rows are cut into chunks of `rows_per_chunk`; one team owns a chunk: its piece of w
// (32 KB) stays in L1 and its piece of V in L2/L3 while the team walks the columns, each
// column's piece read contiguously. Measured on 1.1 M rows (bench_gmres): pieces of 4 KB
// (512 rows) run at 7 GB/s, a fifth of the triad (each piece is one page, so the hardware
// prefetcher restarts on every column); 16–64 KB pieces at 14–19 GB/s, half of it.
// Each chunk writes its partial sums into its row of `partials`
// (chunk, c + 1: the c dot products, then ‖w‖²), and ChunkSums adds the chunks in their
// order: a fixed summation order, so the result does not depend on the thread count.
#include <Kokkos_Core.hpp>

namespace rouleau {

struct Project {};
struct SubtractAndProject {};
struct SubtractAndNorm {};

struct GramSchmidtSweep {
  using Team = Kokkos::TeamPolicy<>::member_type;
  static constexpr int rows_per_chunk = 4096;

  Kokkos::View<const double**, Kokkos::LayoutLeft> basis;  // V (n, c)
  Kokkos::View<double*> w;                                  // the vector being orthogonalized (n)
  Kokkos::View<const double*> subtracted;                   // the coefficients of V to take off w (c)
  Kokkos::View<double**, Kokkos::LayoutRight> partials;     // (chunk, c + 1)

  static int chunks(long n) { return static_cast<int>((n + rows_per_chunk - 1) / rows_per_chunk); }

  KOKKOS_INLINE_FUNCTION void operator()(Project, const Team& team) const { project(team); }
  KOKKOS_INLINE_FUNCTION void operator()(SubtractAndProject, const Team& team) const {
    subtract(team);
    project(team);
  }
  KOKKOS_INLINE_FUNCTION void operator()(SubtractAndNorm, const Team& team) const {
    subtract(team);
    const long begin = first_row(team), end = last_row(team);
    double sum = 0.0;
    Kokkos::parallel_reduce(
        Kokkos::TeamThreadRange(team, quads(begin, end)),
        [&](const long q, double& s) { s += four_row_dot(w, end, begin + 4 * q); }, sum);
    const int chunk = team.league_rank(), norm_column = static_cast<int>(basis.extent(1));
    Kokkos::single(Kokkos::PerTeam(team), [&]() { partials(chunk, norm_column) = sum; });
  }

 private:
  KOKKOS_INLINE_FUNCTION long first_row(const Team& team) const {
    return static_cast<long>(team.league_rank()) * rows_per_chunk;
  }
  KOKKOS_INLINE_FUNCTION long last_row(const Team& team) const {
    const long end = first_row(team) + rows_per_chunk, n = static_cast<long>(w.extent(0));
    return end < n ? end : n;
  }
  KOKKOS_INLINE_FUNCTION static long quads(long begin, long end) { return (end - begin + 3) / 4; }

  // Σ a_i b_i over rows i0 … i0+3 (those below `end`), summed as a tree so that the
  // running sum's dependency chain has one add per four rows.
  template <class VectorA>
  KOKKOS_INLINE_FUNCTION double four_row_dot(const VectorA& a, long end, long i0) const {
    if (i0 + 3 < end) return (a(i0) * w(i0) + a(i0 + 1) * w(i0 + 1)) + (a(i0 + 2) * w(i0 + 2) + a(i0 + 3) * w(i0 + 3));
    double s = 0.0;
    for (long i = i0; i < end; ++i) s += a(i) * w(i);
    return s;
  }

  // w_i ← w_i − Σ_j V_ij s_j over the chunk, column by column. A team thread owns the
  // same rows in every column, so no two threads touch one w_i.
  KOKKOS_INLINE_FUNCTION void subtract(const Team& team) const {
    const long begin = first_row(team), end = last_row(team);
    const int columns = static_cast<int>(basis.extent(1));
    for (int j = 0; j < columns; ++j) {
      const double s = subtracted(j);
      const auto v = Kokkos::subview(basis, Kokkos::ALL(), j);
      Kokkos::parallel_for(Kokkos::TeamThreadRange(team, begin, end), [&](const long i) { w(i) -= s * v(i); });
    }
    team.team_barrier();
  }

  // partials(chunk, j) = Σ_{i in chunk} V_ij w_i for every column j.
  KOKKOS_INLINE_FUNCTION void project(const Team& team) const {
    const long begin = first_row(team), end = last_row(team);
    const int columns = static_cast<int>(basis.extent(1)), chunk = team.league_rank();
    for (int j = 0; j < columns; ++j) {
      const auto v = Kokkos::subview(basis, Kokkos::ALL(), j);
      double dot = 0.0;
      Kokkos::parallel_reduce(
          Kokkos::TeamThreadRange(team, quads(begin, end)),
          [&](const long q, double& s) { s += four_row_dot(v, end, begin + 4 * q); }, dot);
      Kokkos::single(Kokkos::PerTeam(team), [&]() { partials(chunk, j) = dot; });
    }
  }
};

// totals(j) = Σ_chunk partials(chunk, j), chunks in order, for the first `columns` columns.
struct ChunkSums {
  Kokkos::View<const double**, Kokkos::LayoutRight> partials;
  Kokkos::View<double*> totals;
  int chunks;

  KOKKOS_INLINE_FUNCTION void operator()(const int j) const {
    double sum = 0.0;
    for (int chunk = 0; chunk < chunks; ++chunk) sum += partials(chunk, j);
    totals(j) = sum;
  }
};

}  // namespace rouleau
