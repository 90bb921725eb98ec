#pragma once
// The two steps every compressed-row (CSR) build of rouleau shares: row counts turned into
// row offsets by an exclusive scan, and the marked indices gathered in order. The builds
// themselves (the RKPM supports, the Morse neighbour list and its pairs in range, the
// binned points) count each row with the same loop that later fills it, so the count and
// the fill cannot disagree.
#include <Kokkos_Core.hpp>
#include <cstddef>
#include <string>
#include <utility>

namespace rouleau {

// offsets(i), i < rows: row i's count on entry (offsets(rows) is ignored); on return
// offsets(i) = Σ_{k<i} count_k and offsets(rows) = the total, which is returned.
template <class ExecSpace, class Offsets>
int counts_to_offsets(const char* label, const Offsets& offsets, const int rows) {
  int total = 0;
  Kokkos::parallel_scan(
      label, Kokkos::RangePolicy<ExecSpace>(0, rows + 1),
      KOKKOS_LAMBDA(const int i, int& sum, const bool final) {
        const int count = i < rows ? offsets(i) : 0;
        if (final) offsets(i) = sum;
        sum += count;
      },
      total);
  return total;
}

// `view` holds at least n entries: reallocated, with a fifth more room, when shorter (so a
// list that grows slowly is not reallocated at every build).
template <class View>
void ensure_length(View& view, const std::size_t n, const char* label) {
  if (view.extent(0) < n) view = View(std::string(label), n + n / 5);
}

// `view` as n zeros: reallocated when its length is not n, else cleared (flags marked anew
// at every build).
template <class View>
void zero_with_length(View& view, const std::size_t n, const char* label) {
  if (view.extent(0) != n)
    view = View(std::string(label), n);
  else
    Kokkos::deep_copy(view, 0);
}

// The indices i < n with marked(i), ascending, gathered into `buffer` (grown when short):
// returns the view of them at the buffer's start.
template <class ExecSpace, class Marked, class Buffer>
Buffer gather_marked(const char* label, const int n, const Marked& marked, Buffer& buffer) {
  int count = 0;
  Kokkos::parallel_reduce(
      label, Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i, int& sum) { sum += marked(i) ? 1 : 0; },
      count);
  ensure_length(buffer, static_cast<std::size_t>(count), label);
  const Buffer gathered = Kokkos::subview(buffer, std::make_pair(0, count));
  // position of i = the number of marked indices before it
  Kokkos::parallel_scan(
      label, Kokkos::RangePolicy<ExecSpace>(0, n), KOKKOS_LAMBDA(const int i, int& before, const bool final) {
        const int mark = marked(i) ? 1 : 0;
        if (final && mark) gathered(before) = i;
        before += mark;
      });
  return gathered;
}

}  // namespace rouleau
