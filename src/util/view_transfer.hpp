#pragma once
// Device Views to flat host vectors and back, entity-major (x0 y0 z0 x1 ...) whatever the
// View's layout: the form in which checkpoints (io/checkpoint_file.hpp) store state.
#include <Kokkos_Core.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace rouleau {

// The values of a rank-1 or rank-2 View, row by row.
template <class View>
std::vector<typename View::non_const_value_type> to_flat_vector(const View& view) {
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  std::vector<typename View::non_const_value_type> values;
  if constexpr (View::rank == 1) {
    values.resize(host.extent(0));
    for (std::size_t i = 0; i < host.extent(0); ++i) values[i] = host(i);
  } else {
    const std::size_t columns = host.extent(1);
    values.resize(host.extent(0) * columns);
    for (std::size_t i = 0; i < host.extent(0); ++i)
      for (std::size_t k = 0; k < columns; ++k) values[i * columns + k] = host(i, k);
  }
  return values;
}

// Fills `view` from `values` written by to_flat_vector. Throws std::runtime_error naming
// `what` when the sizes differ.
template <class View, class T>
void from_flat_vector(const std::vector<T>& values, const View& view, const std::string& what) {
  std::size_t size = view.extent(0);
  if constexpr (View::rank == 2) size *= view.extent(1);
  if (values.size() != size)
    throw std::runtime_error(what + ": " + std::to_string(values.size()) + " values for a field of " +
                             std::to_string(size));
  auto host = Kokkos::create_mirror_view(view);
  if constexpr (View::rank == 1) {
    for (std::size_t i = 0; i < host.extent(0); ++i) host(i) = values[i];
  } else {
    const std::size_t columns = host.extent(1);
    for (std::size_t i = 0; i < host.extent(0); ++i)
      for (std::size_t k = 0; k < columns; ++k) host(i, k) = values[i * columns + k];
  }
  Kokkos::deep_copy(view, host);
}

// A device copy of a host list (index lists, e.g. the nodes an exchange sends).
template <class T>
Kokkos::View<T*> device_copy(const std::vector<T>& values, const std::string& label) {
  Kokkos::View<T*> view(label, values.size());
  auto host = Kokkos::create_mirror_view(view);
  for (std::size_t i = 0; i < values.size(); ++i) host(i) = values[i];
  Kokkos::deep_copy(view, host);
  return view;
}

}  // namespace rouleau
