#pragma once
// A scope guard over Kokkos::Profiling::pushRegion/popRegion (Kokkos 3.4 has no
// ScopedRegion), so profilers show rouleau's stage names.
#include <Kokkos_Core.hpp>
#include <string>

namespace rouleau {

class ProfilingRegion {
 public:
  explicit ProfilingRegion(const std::string& name) { Kokkos::Profiling::pushRegion(name); }
  ~ProfilingRegion() { Kokkos::Profiling::popRegion(); }
  ProfilingRegion(const ProfilingRegion&) = delete;
  ProfilingRegion& operator=(const ProfilingRegion&) = delete;
};

}  // namespace rouleau
