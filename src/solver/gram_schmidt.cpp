#include "solver/gram_schmidt.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernels/gram_schmidt.hpp"

namespace rouleau {

GramSchmidt::GramSchmidt(long n, int max_columns, const Communicator* communicator)
    : partials_("rouleau::GramSchmidt::partials", GramSchmidtSweep::chunks(n), max_columns + 1),
      coefficients_("rouleau::GramSchmidt::coefficients", 2 * (max_columns + 1)),
      coefficients_host_(Kokkos::create_mirror_view(coefficients_)),
      communicator_(communicator && communicator->size() > 1 ? communicator : nullptr) {}

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

// totals(j) for j in [first, last) summed over the ranks (through the host).
void sum_over_ranks(const Communicator& communicator, const Kokkos::View<double*>& totals,
                    const Kokkos::View<double*>::HostMirror& host, int first, int last) {
  const auto range = Kokkos::make_pair(first, last);
  const auto device_part = Kokkos::subview(totals, range);
  const auto host_part = Kokkos::subview(host, range);
  Kokkos::deep_copy(host_part, device_part);
  communicator.sum(host_part.data(), last - first);
  Kokkos::deep_copy(device_part, host_part);
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
  const int second = static_cast<int>(partials_.extent(1));  // where c2 starts in coefficients_
  const auto first_pass = Kokkos::subview(coefficients_, Kokkos::make_pair(0, second));
  const auto second_pass = Kokkos::subview(coefficients_, Kokkos::make_pair(second, 2 * second));
  GramSchmidtSweep sweep{V, w, first_pass, partials_};
  // Across ranks each sum must be whole before a sweep subtracts with it.
  const auto whole = [&](const Kokkos::View<double*>& totals, int first, int last) {
    if (communicator_) sum_over_ranks(*communicator_, totals, coefficients_host_, first, last);
  };
  // c1 = Vᵀw
  run_sweep<Project>(sweep, chunks, "rouleau::GramSchmidt::project");
  sum_chunks(sweep, chunks, first_pass, 0, columns);
  whole(coefficients_, 0, columns);
  // w ← w − V c1, c2 = Vᵀw
  run_sweep<SubtractAndProject>(sweep, chunks, "rouleau::GramSchmidt::subtract_and_project");
  sum_chunks(sweep, chunks, second_pass, 0, columns);
  whole(coefficients_, second, second + columns);
  // w ← w − V c2, ‖w‖² into first_pass(columns)
  sweep.subtracted = second_pass;
  run_sweep<SubtractAndNorm>(sweep, chunks, "rouleau::GramSchmidt::subtract_and_norm");
  sum_chunks(sweep, chunks, first_pass, columns, columns + 1);
  whole(coefficients_, columns, columns + 1);
  Kokkos::deep_copy(coefficients_host_, coefficients_);
  for (int j = 0; j < columns; ++j) h[j] = coefficients_host_(j) + coefficients_host_(second + j);
  return std::sqrt(coefficients_host_(columns));
}

}  // namespace rouleau
