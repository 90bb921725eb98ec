#include "solver/gram_schmidt.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernels/gram_schmidt.hpp"

namespace rouleau {

GramSchmidt::GramSchmidt(long n, int max_columns)
    : partials_("rouleau::GramSchmidt::partials", GramSchmidtSweep::chunks(n), max_columns + 1),
      first_pass_("rouleau::GramSchmidt::first_pass", max_columns + 1),
      second_pass_("rouleau::GramSchmidt::second_pass", max_columns + 1),
      first_pass_host_(Kokkos::create_mirror_view(first_pass_)),
      second_pass_host_(Kokkos::create_mirror_view(second_pass_)) {}

namespace {

template <class Sweep>
void run_sweep(const GramSchmidtSweep& sweep, int chunks, const char* label) {
  Kokkos::parallel_for(label, Kokkos::TeamPolicy<Sweep>(chunks, Kokkos::AUTO), sweep);
}

// totals(j) = Σ_chunk partials(chunk, j) for j in [first, last).
void sum_chunks(const GramSchmidtSweep& sweep, int chunks, const Kokkos::View<double*>& totals, int first, int last) {
  Kokkos::parallel_for("rouleau::GramSchmidt::chunk_sums", Kokkos::RangePolicy<>(first, last),
                       ChunkSums{sweep.partials, totals, chunks});
}

}  // namespace

double GramSchmidt::orthogonalize(const Kokkos::View<const double**, Kokkos::LayoutLeft>& V,
                                  const Kokkos::View<double*>& w, double* h) {
  const int columns = static_cast<int>(V.extent(1));
  if (columns + 1 > static_cast<int>(partials_.extent(1)) || GramSchmidtSweep::chunks(static_cast<long>(w.extent(0))) >
                                                                  static_cast<int>(partials_.extent(0)))
    throw std::logic_error("rouleau::GramSchmidt::orthogonalize: a basis of " + std::to_string(columns) +
                           " columns of length " + std::to_string(w.extent(0)) + " exceeds the workspace");
  const int chunks = GramSchmidtSweep::chunks(static_cast<long>(w.extent(0)));
  GramSchmidtSweep sweep{V, w, first_pass_, partials_};
  // c1 = Vᵀw
  run_sweep<Project>(sweep, chunks, "rouleau::GramSchmidt::project");
  sum_chunks(sweep, chunks, first_pass_, 0, columns);
  // w ← w − V c1, c2 = Vᵀw
  run_sweep<SubtractAndProject>(sweep, chunks, "rouleau::GramSchmidt::subtract_and_project");
  sum_chunks(sweep, chunks, second_pass_, 0, columns);
  // w ← w − V c2, ‖w‖² into first_pass_(columns)
  sweep.subtracted = second_pass_;
  run_sweep<SubtractAndNorm>(sweep, chunks, "rouleau::GramSchmidt::subtract_and_norm");
  sum_chunks(sweep, chunks, first_pass_, columns, columns + 1);
  Kokkos::deep_copy(first_pass_host_, first_pass_);
  Kokkos::deep_copy(second_pass_host_, second_pass_);
  for (int j = 0; j < columns; ++j) h[j] = first_pass_host_(j) + second_pass_host_(j);
  return std::sqrt(first_pass_host_(columns));
}

}  // namespace rouleau
