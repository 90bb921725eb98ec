// kokkos_runtime_info(): the Kokkos and KokkosKernels versions, the back ends built in,
// the default execution space and its thread count, for `rouleau info`.
#include "run/kokkos_runtime_info.hpp"

#include <Kokkos_Core.hpp>

#include "rouleau_version.hpp"

namespace rouleau {

std::vector<std::pair<std::string, std::string>> kokkos_runtime_info() {
  std::vector<std::pair<std::string, std::string>> info;
  info.emplace_back("kokkos", ROULEAU_KOKKOS_VERSION);
  info.emplace_back("kokkos-kernels", ROULEAU_KOKKOSKERNELS_VERSION);
  std::string backends;
#ifdef KOKKOS_ENABLE_SERIAL
  backends += "Serial ";
#endif
#ifdef KOKKOS_ENABLE_OPENMP
  backends += "OpenMP ";
#endif
#ifdef KOKKOS_ENABLE_THREADS
  backends += "Threads ";
#endif
#ifdef KOKKOS_ENABLE_CUDA
  backends += "Cuda ";
#endif
#ifdef KOKKOS_ENABLE_HIP
  backends += "HIP ";
#endif
  if (!backends.empty()) backends.pop_back();
  info.emplace_back("kokkos backends", backends);
  info.emplace_back("default execution space", Kokkos::DefaultExecutionSpace::name());
  info.emplace_back("threads", std::to_string(Kokkos::DefaultHostExecutionSpace().concurrency()));
  return info;
}

}  // namespace rouleau
