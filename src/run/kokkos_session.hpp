#pragma once
// Kokkos started for the lifetime of a KokkosSession, with the thread count of the command
// line (`--threads N` of `rouleau run` and the case drivers) when it gives one; otherwise
// Kokkos reads OMP_NUM_THREADS. The command line itself never reaches Kokkos, so a flag of
// rouleau's can not be taken for one of Kokkos's.
//
// Without OMP_PROC_BIND in the environment, Kokkos's OpenMP back end prints four lines of
// advice at every start. When neither OMP_PROC_BIND nor OMP_PLACES is set the OpenMP
// runtime binds no thread, so the session sets OMP_PROC_BIND=false, which says what holds,
// and a run says once, in its log, how to bind the threads (run_report.cpp, from the
// runtime's own omp_get_proc_bind()).
#include <Kokkos_Core.hpp>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli.hpp"

namespace rouleau {

class KokkosSession {
 public:
  KokkosSession(const char* program, int threads) : arguments_{program} {
    if (std::getenv("OMP_PROC_BIND") == nullptr && std::getenv("OMP_PLACES") == nullptr)
      setenv("OMP_PROC_BIND", "false", 0);
    if (threads > 0) arguments_.push_back(kokkos_threads_flag(threads, KOKKOS_VERSION));
    for (std::string& argument : arguments_) argument_pointers_.push_back(argument.data());
    argument_pointers_.push_back(nullptr);
    argument_count_ = static_cast<int>(arguments_.size());
    guard_ = std::make_unique<Kokkos::ScopeGuard>(argument_count_, argument_pointers_.data());
  }

 private:
  std::vector<std::string> arguments_;
  std::vector<char*> argument_pointers_;
  int argument_count_ = 0;
  std::unique_ptr<Kokkos::ScopeGuard> guard_;
};

}  // namespace rouleau
