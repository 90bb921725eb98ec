#include "run/run_case.hpp"

#include <Kokkos_Core.hpp>
#include <sstream>
#include <stdexcept>

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
  info.emplace_back("host threads", std::to_string(Kokkos::DefaultHostExecutionSpace().concurrency()));
  return info;
}

int run_case(const CaseConfig&, const RunOptions&) {
  // Filled in by the fluid solver work (issue 2, in progress).
  throw std::logic_error("rouleau::run_case: the time loop is not built yet");
}

}  // namespace rouleau
