#pragma once
// Shared test helpers: comparing Views with the worst entries printed.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace rouleau::testing {

// Expects |a_i − b_i| ≤ atol + rtol |b_i| for all i; on failure prints the five worst.
template <class ViewA, class ViewB>
void expectAllClose(const ViewA& a, const ViewB& b, double rtol, double atol) {
  auto ha = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), a);
  auto hb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), b);
  ASSERT_EQ(ha.extent(0), hb.extent(0));
  std::vector<std::pair<double, size_t>> excess;
  for (size_t i = 0; i < ha.extent(0); ++i) {
    const double err = std::fabs(ha(i) - hb(i)) - (atol + rtol * std::fabs(hb(i)));
    if (err > 0 || std::isnan(ha(i)) != std::isnan(hb(i))) excess.emplace_back(err, i);
  }
  if (excess.empty()) return;
  std::sort(excess.rbegin(), excess.rend());
  std::ostringstream msg;
  msg << excess.size() << " of " << ha.extent(0) << " entries differ; worst:";
  for (size_t k = 0; k < std::min<size_t>(5, excess.size()); ++k) {
    const size_t i = excess[k].second;
    msg << "\n  [" << i << "] " << ha(i) << " vs " << hb(i);
  }
  ADD_FAILURE() << msg.str();
}

// Relative 2-norm difference ‖a − b‖ / ‖b‖ of two Views.
template <class ViewA, class ViewB>
double relativeDifference(const ViewA& a, const ViewB& b) {
  auto ha = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), a);
  auto hb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), b);
  double d = 0, n = 0;
  for (size_t i = 0; i < ha.extent(0); ++i) {
    d += (ha(i) - hb(i)) * (ha(i) - hb(i));
    n += hb(i) * hb(i);
  }
  return std::sqrt(d / n);
}

}  // namespace rouleau::testing
