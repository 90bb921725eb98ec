#include "run/thread_binding.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif
#ifdef _OPENMP
#include <omp.h>
#endif

namespace rouleau {

std::vector<int> spread_threads_over_cores(const int threads, const std::vector<int>& cpus,
                                           const std::vector<int>& core_of) {
  if (threads < 2 || threads > static_cast<int>(cpus.size()) || core_of.size() != cpus.size()) return {};
  // One CPU per core in the order the cores first appear, then each core's next sibling, …
  std::vector<int> first_of_core, siblings;
  std::vector<int> seen;
  for (std::size_t k = 0; k < cpus.size(); ++k) {
    if (std::find(seen.begin(), seen.end(), core_of[k]) == seen.end()) {
      seen.push_back(core_of[k]);
      first_of_core.push_back(cpus[k]);
    } else {
      siblings.push_back(cpus[k]);
    }
  }
  std::vector<int> bound(threads);
  const int cores = static_cast<int>(first_of_core.size());
  if (threads <= cores) {
    // spread: thread t on core ⌊t · cores / threads⌋
    for (int t = 0; t < threads; ++t) bound[t] = first_of_core[static_cast<long>(t) * cores / threads];
  } else {
    for (int t = 0; t < threads; ++t) bound[t] = t < cores ? first_of_core[t] : siblings[t - cores];
  }
  return bound;
}

namespace {

bool placement_given_by_environment() {
  for (const char* variable : {"OMP_PROC_BIND", "OMP_PLACES", "GOMP_CPU_AFFINITY", "KMP_AFFINITY"})
    if (std::getenv(variable) != nullptr) return true;
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* value = std::getenv(variable); value && std::atoi(value) > 1) return true;
  return false;
}

#if defined(__linux__)
// The core of CPU `cpu`: the first CPU of its thread siblings (itself when unknown).
int core_of_cpu(const int cpu) {
  std::ifstream siblings("/sys/devices/system/cpu/cpu" + std::to_string(cpu) + "/topology/thread_siblings_list");
  int first = cpu;
  if (siblings >> first) return first;
  return cpu;
}

std::vector<int> cpus_of_this_thread() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  std::vector<int> cpus;
  if (pthread_getaffinity_np(pthread_self(), sizeof(mask), &mask) != 0) return cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
    if (CPU_ISSET(cpu, &mask)) cpus.push_back(cpu);
  return cpus;
}
#endif

}  // namespace

std::vector<int> bind_host_threads(const int threads) {
#if defined(__linux__) && defined(_OPENMP)
  if (placement_given_by_environment()) return {};
  const std::vector<int> cpus = cpus_of_this_thread();
  std::vector<int> core_of;
  for (const int cpu : cpus) core_of.push_back(core_of_cpu(cpu));
  const std::vector<int> bound = spread_threads_over_cores(threads, cpus, core_of);
  if (bound.empty()) return {};
  // The runtime keeps the threads of a team between parallel regions of the same size, so
  // binding them once here binds the threads every later parallel loop runs on.
  int failures = 0;
#pragma omp parallel num_threads(threads) reduction(+ : failures)
  {
    cpu_set_t mask;
    CPU_ZERO(&mask);
    CPU_SET(bound[omp_get_thread_num()], &mask);
    failures += pthread_setaffinity_np(pthread_self(), sizeof(mask), &mask) != 0 ? 1 : 0;
  }
  if (failures > 0) return {};
  return bound;
#else
  (void)threads;
  return {};
#endif
}

std::string describe_host_thread_binding(const int threads) {
#if defined(__linux__) && defined(_OPENMP)
  if (threads < 2) return "";
  std::vector<int> cpu(threads, -1);  // the one CPU of thread t, or −1 when it may use several
#pragma omp parallel num_threads(threads)
  {
    const std::vector<int> mine = cpus_of_this_thread();
    if (mine.size() == 1) cpu[omp_get_thread_num()] = mine.front();
  }
  if (std::find(cpu.begin(), cpu.end(), -1) != cpu.end())
    return "host threads free to move between CPUs (as OMP_PROC_BIND, OMP_PLACES or an MPI launcher said; "
           "without them rouleau binds one per core)";
  std::ostringstream line;
  line << "host threads bound one per CPU:";
  for (int t = 0; t < threads; ++t) line << (t > 0 ? ", " : " ") << cpu[t];
  return line.str();
#else
  (void)threads;
  return "";
#endif
}

}  // namespace rouleau
