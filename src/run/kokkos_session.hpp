#pragma once
// Kokkos started for the lifetime of a KokkosSession, with the thread count of the command
// line (`--threads N` of `rouleau run` and the case drivers) when it gives one; otherwise
// Kokkos reads OMP_NUM_THREADS. The command line itself never reaches Kokkos, so a flag of
// rouleau's can not be taken for one of Kokkos's.
//
// The host threads are then bound one per core unless the environment says how to place
// them (run/thread_binding.hpp: a run beside other work is about twice as fast so). Without
// OMP_PROC_BIND in the environment, Kokkos's OpenMP back end prints four lines of advice at
// every start; the OpenMP runtime has read its environment before main, so the session sets
// OMP_PROC_BIND=false for Kokkos alone, and a run says once, in its log, where its threads
// are (run_report.cpp).
#include <Kokkos_Core.hpp>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli.hpp"
#include "run/thread_binding.hpp"

namespace rouleau {

class KokkosSession {
 public:
  KokkosSession(const char* program, int threads) : arguments_{program} {
    const bool placement_left_open = std::getenv("OMP_PROC_BIND") == nullptr && std::getenv("OMP_PLACES") == nullptr;
    if (placement_left_open) setenv("OMP_PROC_BIND", "false", 0);
    if (threads > 0) arguments_.push_back(kokkos_threads_flag(threads, KOKKOS_VERSION));
    for (std::string& argument : arguments_) argument_pointers_.push_back(argument.data());
    argument_pointers_.push_back(nullptr);
    argument_count_ = static_cast<int>(arguments_.size());
    guard_ = std::make_unique<Kokkos::ScopeGuard>(argument_count_, argument_pointers_.data());
    if (placement_left_open) {
      unsetenv("OMP_PROC_BIND");  // what the user set decides, not the line above
      bind_host_threads(Kokkos::DefaultHostExecutionSpace().concurrency());
    }
  }

 private:
  std::vector<std::string> arguments_;
  std::vector<char*> argument_pointers_;
  int argument_count_ = 0;
  std::unique_ptr<Kokkos::ScopeGuard> guard_;
};

}  // namespace rouleau
