#pragma once
// What Kokkos this program runs on, for `rouleau info`. This header includes no Kokkos
// header.
#include <string>
#include <utility>
#include <vector>

namespace rouleau {

// Name/value lines for `rouleau info`: Kokkos version and enabled backends, default
// execution space and its concurrency (threads), KokkosKernels version.
std::vector<std::pair<std::string, std::string>> kokkos_runtime_info();

}  // namespace rouleau
