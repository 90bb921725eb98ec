#pragma once
// Sums of per-element contributions through a Kokkos ScatterView: per-thread copies on
// CPU threads (ScatterDuplicated), one atomically updated buffer on GPUs and Serial.
// The buffer is kept by the caller and reused call after call (no allocation per call).
#include <Kokkos_Core.hpp>
#include <Kokkos_ScatterView.hpp>
#include <type_traits>

namespace rouleau {

// Whether a ScatterView keeps per-thread copies (CPU threads) or adds atomically into
// one buffer (GPUs, Serial).
template <class Scatter>
struct IsDuplicated : std::false_type {};
template <class D, class L, class Dev, class Op, class C>
struct IsDuplicated<Kokkos::Experimental::ScatterView<D, L, Dev, Op, Kokkos::Experimental::ScatterDuplicated, C>>
    : std::true_type {};

// target = the sum of the scatter buffer's contributions: its per-thread copies added
// up, or its one buffer copied (Kokkos 3.4's contribute_into adds nothing from a
// non-duplicated buffer into another View).
template <class Target, class Scatter>
void gather_into(const Target& target, const Scatter& scatter) {
  if constexpr (IsDuplicated<Scatter>::value) {
    Kokkos::deep_copy(target, 0.0);
    scatter.contribute_into(target);
  } else {
    Kokkos::deep_copy(target, scatter.subview());
  }
}

// target += the scatter buffer's contributions.
template <class Target, class Scatter>
void add_into(const Target& target, const Scatter& scatter) {
  if constexpr (IsDuplicated<Scatter>::value) {
    scatter.contribute_into(target);
  } else {
    using ExecSpace = typename Scatter::execution_space;
    const auto sums = scatter.subview();
    Kokkos::parallel_for(
        "rouleau::add_into", Kokkos::RangePolicy<ExecSpace>(0, target.extent(0)),
        KOKKOS_LAMBDA(const int i) { target(i) += sums(i); });
  }
}

}  // namespace rouleau
